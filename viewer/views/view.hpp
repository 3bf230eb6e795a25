#pragma once
// The inspector's views, each one descriptor registered once (views/view_registry.cpp): its name,
// its title, what it reads from the inspection, how it draws into a VTK renderer, and which
// choosers and interactions the window gives it. The same descriptor serves the window and
// `shadowlab render`; nothing else names a view in code.
#include <deque>
#include <functional>
#include <string>

#include "views/view_options.hpp"

class vtkRenderer;

namespace shadowlab {

// Which of the ViewOptions a view reads: the window's panel shows these choosers beside it, and
// the window redraws it when the Controls panel's "shadow only" flips.
struct ViewChoosers {
    bool error = false;          // verdicts or the signed visibility error (ErrorShown)
    bool aliasing = false;       // m or one of its factors (AliasingShown)
    bool texture = false;        // depth or the moments a vsm or evsm filter reads (TextureShown)
    bool overlay = false;        // shadows alone, the map per pixel or texels per pixel (MapOverlay)
    bool preset = false;         // orbit, from the light, side (SpacePreset)
    bool scene_in_ppls = false;  // the scene's triangles drawn in post-perspective light space
    bool shadow_only = false;    // the Controls panel's: white where lit, black where shadowed (lit_mask)
};

// What a drag in the window's panel does.
enum class ViewDrag {
    pans_image,           // pans and zooms a flat picture
    orbits,               // orbits the view's camera; the next redraw places the view's own again
    orbits_kept,          // orbits it, kept across redraws until the view or its preset changes
    steers_scene_camera,  // moves the scene's camera (the method computes again); unlocked, the scene
                          // camera's aspect follows the first panel that steers it
};

struct ViewInteraction {
    bool draws_steps = false;           // draws the trace step chosen: redrawn when another is chosen
    bool through_scene_camera = false;  // drawn through the scene's camera, keeping its aspect
                                        // (letterboxed in a panel; `render` draws the camera's image size)
    ViewDrag drag = ViewDrag::orbits;
    bool handles = false;  // the light and the camera as handles the user drags to move them
};

// Computes the inspection's lazy parts the view will read (the depth maps, a reference, an error
// against it), on the window's worker thread, so that drawing only draws.
using PrepareView = std::function<void(const Inspection& inspection, const ViewOptions& options)>;
// Fills an empty renderer with the view and places its camera.
using BuildView =
    std::function<ViewReport(vtkRenderer* renderer, const Inspection& inspection, const ViewOptions& options)>;

struct View {
    std::string name;     // as on the command line: "shadowmap"
    std::string title;    // as in the window: "Shadow map"
    PrepareView prepare;  // empty: the view reads nothing lazy (the Camera view draws on the GPU)
    BuildView build;
    ViewChoosers choosers;
    ViewInteraction interaction;
};
inline bool operator==(const View& a, const View& b) { return a.name == b.name; }

// Every view, in the order the window's choosers list them: the shipped ones, then any registered
// later. A deque: registering one more never moves the others, so pointers to entries stay valid.
const std::deque<View>& all_views();
const View* find_view(const std::string& name);  // nullptr when no view has that name
// The view, or std::invalid_argument "unknown view 'x' (known: camera, world, ...)".
const View& view_or_throw(const std::string& name);
std::string view_names(const std::string& separator = ", ");
// Adds a view after the others (a test's throw-away view, a plug-in), before the window is built:
// its panels list the views there are when it opens. Throws std::invalid_argument when the name is
// taken or the view cannot draw (no build).
void register_view(View view);

// The view built into an empty renderer. The camera view installs a ShadowMapPass on the renderer
// (a StencilVolumePass for a geometric technique). Throws std::invalid_argument for a step id the
// trace lacks.
ViewReport build_view(vtkRenderer* renderer, const Inspection& inspection, const View& view,
                      const ViewOptions& options);
// The view's prepare step, if it has one.
void prepare_view(const Inspection& inspection, const View& view, const ViewOptions& options);

}  // namespace shadowlab
