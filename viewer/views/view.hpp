#pragma once
// The inspector's views, each drawn into a VTK renderer from one Inspection: the same code serves
// the window and `shadowlab render`.
#include <optional>
#include <string>
#include <vector>

#include "model/inspection.hpp"
#include "render/map_overlay.hpp"

class vtkRenderer;

namespace shadowlab {

enum class ViewKind { camera, world, light, ppls, shadow_map, texels, error, stencil };

const char* to_string(ViewKind view);                         // as on the command line: "shadowmap"
const char* view_title(ViewKind view);                        // as in the window: "Shadow map"
std::optional<ViewKind> view_named(const std::string& name);  // nullopt for an unknown name
const std::vector<ViewKind>& all_views();
// Does the view draw the chosen trace step (World, Light space, PPLS)? The others do not change with it.
bool shows_steps(ViewKind view);
// Is the view drawn through the scene's camera (Camera, Texels), so that its picture keeps the camera's aspect?
bool looks_through_scene_camera(ViewKind view);

// Which aliasing the Error view paints: Lloyd's m, or one of its two factors (ShadowError).
enum class AliasingShown { total, perspective, projection };

// What the Error view paints: each pixel's verdict against the reference (false shadow, false light,
// Lloyd's m beneath), or its signed visibility error, method − reference (ShadowError::visibility);
// automatic: the signed error where shadows are soft, the verdicts where they are hard.
enum class ErrorShown { automatic, verdicts, signed_visibility };
// Are shadows soft, so that a verdict (shadowed or lit) no longer says how far a pixel is off? The
// light has a size (the reference is soft) or the filter is not hard (the method's visibility is
// fractional).
bool soft_shadows(const Inspection& inspection);
// The Error view's choice resolved: does it paint the signed visibility error?
bool shows_signed_error(const Inspection& inspection, ErrorShown shown);

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
    ErrorShown error = ErrorShown::automatic;       // error view: verdicts or signed visibility error
    TextureShown texture = TextureShown::depth;     // shadow map view: depth or the moments VSM reads
};

// What a view could not draw, for the window's status line: "12 triangles behind w = 0 left out".
struct ViewReport {
    std::vector<std::string> notes;
};

// Fills an empty renderer with the view and places its camera. The camera view installs a
// ShadowMapPass on the renderer (a StencilVolumePass for a geometric technique). Throws
// std::invalid_argument for a step id the trace lacks.
ViewReport build_view(vtkRenderer* renderer, const Inspection& inspection, ViewKind view, const ViewOptions& options);

// Computes now the inspection's lazy parts that build_view would read for this view (the depth maps,
// a reference, an error against it), so that a worker thread pays for them and drawing only draws.
void prepare_view(const Inspection& inspection, ViewKind view, const ViewOptions& options);

}  // namespace shadowlab
