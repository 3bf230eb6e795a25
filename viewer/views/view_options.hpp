#pragma once
// What a view is asked to draw beyond the inspection: the trace step, and each chooser's choice
// (the window's panels set them, `shadowlab render` from its flags). A view reads those its
// descriptor names (views/view.hpp, ViewChoosers).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/inspection.hpp"
#include "render/map_overlay.hpp"

namespace shadowlab {

// Which aliasing the Error view paints: Lloyd's m, or one of its two factors (ShadowError).
enum class AliasingShown { total, perspective, projection };

// What the Error view paints: each pixel's verdict against the reference (false shadow, false light,
// Lloyd's m beneath), its signed visibility error, method − reference (ShadowError::visibility), or
// each misclassified pixel's cause (ShadowError::causes, in the colours of metrics/pixel_cause.hpp);
// automatic: the signed error where shadows are soft, the verdicts where they are hard.
enum class ErrorShown { automatic, verdicts, signed_visibility, causes };
// Each choice once: its name on the command line (`render --error causes`), its title in the window.
struct ErrorChoice {
    ErrorShown shown;
    const char* name;
    const char* title;
};
const std::vector<ErrorChoice>& all_error_choices();
std::optional<ErrorShown> error_shown_named(const std::string& name);  // nullopt for an unknown name
// Are shadows soft, so that a verdict (shadowed or lit) no longer says how far a pixel is off? The
// light has a size (the reference is soft) or the filter is not hard (the method's visibility is
// fractional).
bool soft_shadows(const Inspection& inspection);
// The Error view's choice resolved: does it paint the signed visibility error?
bool shows_signed_error(const Inspection& inspection, ErrorShown shown);
// Does it paint Lloyd's m (or a factor) beneath the verdicts? A map's verdicts only.
bool shows_aliasing(const Inspection& inspection, ErrorShown shown);

// What the Shadow map view paints per texel: the stored depth, or, for a filter that reads moments
// (vsm, evsm), the blurred moments' mean or standard deviation √(m₂ − m₁²) (lookup/moment_map.hpp).
enum class TextureShown { depth, moment_mean, moment_deviation };

// How the World, Light space and PPLS views are looked at: a free perspective orbit, or
// orthographic along the light (what the map sees) or from the side (in the plane of the light and
// the view direction, where a warp shows).
enum class SpacePreset { orbit, from_light, side };
const char* to_string(SpacePreset preset);                               // "orbit", "light", "side"
std::optional<SpacePreset> space_preset_named(const std::string& name);  // nullopt for an unknown name
const std::vector<SpacePreset>& all_space_presets();

struct ViewOptions {
    std::string step;                         // the trace step to highlight; empty: the method's last step
    SpacePreset preset = SpacePreset::orbit;  // World, Light space, PPLS: how the camera looks
    bool scene_in_ppls = true;              // PPLS: draw the scene's triangles (clipped to the unit cube and a margin)
    bool lit_mask = false;                  // camera view: white where lit, black where shadowed, unlit colours
    MapOverlay overlay = MapOverlay::none;  // camera view of a map method: each fragment's map or texels per pixel
    int width = 0, height = 0;              // error view: the camera image it measures (0: 640 x 640 / aspect)
    AliasingShown aliasing = AliasingShown::total;  // error view: the heat map's quantity
    ErrorShown error = ErrorShown::automatic;       // error view: verdicts, signed visibility error or causes
    TextureShown texture = TextureShown::depth;     // shadow map view: depth or the moments VSM reads
    // Difference view: the other configuration of compare mode (B, the inspection drawn being A),
    // judged against the same reference. None: the view says how to give it one.
    std::shared_ptr<const Inspection> compared;
};

// A legend's line: a swatch of the colour and what it stands for.
struct LegendEntry {
    glm::dvec3 colour;
    std::string text;
};

// What a view could not draw, for the window's status line: "12 triangles behind w = 0 left out";
// and what its legend lists, where a page shows it beside the view (the space views').
struct ViewReport {
    std::vector<std::string> notes;
    std::vector<LegendEntry> legend;
};

}  // namespace shadowlab
