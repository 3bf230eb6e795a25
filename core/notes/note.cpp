#include "notes/note.hpp"

#include <stdexcept>

namespace shadowlab {

const std::vector<NoteInfo>& all_note_kinds() {
    using enum NoteKind;
    constexpr NoteCategory F = NoteCategory::fallback, L = NoteCategory::limit;
    static const std::vector<NoteInfo> kinds{
        {empty_scene, F, "empty scene", "no object to fit a map to: the identity map"},
        {empty_body, F, "empty intersection body", "the view frustum does not meet the scene: the uniform map"},
        {behind_light, F, "points behind the light", "a spot or point light's map cannot cover them: left out"},
        {outside_cone, F, "points outside the light's cone", "the map covers the cone only"},
        {not_directional, F, "not a directional light", "a warp for directional lights only: the focused map"},
        {nothing_to_warp, F, "no caster can shadow a visible receiver", "nothing to warp: the focused map"},
        {miners_lamp, F, "miner's lamp", "light nearly along the view: a warp gains nothing, the focused map"},
        {empty_focus_region, F, "empty focus region", "no caster's light rays meet a receiver: the focused map"},
        {parallel_light, F, "light parallel to the view", "the warp degenerates: the focused (or unwarped) map"},
        {degenerate_centre_line, F, "degenerate centre line", "TSM's centre line has no length: the focused map"},
        {focus_out_of_range, F, "focus point out of the 80% rule's range", "TSM's trapezoid fails: the focused map"},
        {no_visible_receiver, F, "no visible receiver",
         "the camera's depth image shows none: the frustum's depth bounds"},
        {directional_light, F, "a directional light",
         "an omnidirectional map needs a light's position: the focused map"},
        {margin_reduced, F, "margin reduced",
         "a tetrahedron face's margin cut to a twelfth of the texture's side: each face at most twice its size"},
        {no_depth_image, F, "no camera depth image",
         "visible depth bounds not measured here: the frustum's depth bounds"},
        {view_outside_cone, F, "view outside the spot's cone",
         "the camera sees nothing the spot lights: the focused map"},
        {light_on_region, F, "light on the region to cover",
         "in the camera's post-perspective space the light sees the region wider than one map holds: the focused map"},
        {warp_not_needed, F, "no warp needed",
         "the spot's own perspective already spreads texels as the eye needs them: the focused map"},
        {log_range_short, F, "log range too short",
         "LogPSM's warp spans under e^0.1 in distance (far / near < 1.105): its logarithm would ask more than a "
         "float's precision of the GPU, and is nearly linear anyway: the perspective warp alone"},
        {no_light_axis, F, "point light without an axis",
         "the warp runs after the light's own perspective, which needs an axis and a cone: the focused map"},
        {no_matrices, F, "no matrices", "the custom method's matrices setting names no file: the focused map"},
        {orthographic_camera, F, "orthographic camera",
         "its rays are parallel, so its post-perspective space is an affine image of the world and the view spreads "
         "texels evenly in depth: nothing to warp, the focused map"},
        {over_page_budget, F, "pages over the budget",
         "the view marked more pages than the physical pool holds: the resolution bias rises until they fit, every "
         "point's texels wider by the same share (UE5's dynamic resolution)"},
        {outside_clipmap, F, "points beyond the clipmap",
         "seen receivers farther from the camera than the coarsest level reaches: no page holds them, they read lit"},
        {warp_loses, F, "warp loses to the focused map",
         "measured, the warp misclassifies more than twice the focused map's share (and 0.05 percentage points "
         "more): the cause and the numbers follow; the focused map serves this view better"},
        {light_along_view, F, "light along the view",
         "the light travels (almost) along the view direction, so no one plane holds both: the flatland plane "
         "is the one of the view direction and the camera's up"},
        {blend_read_as_mask, F, "BLEND caster read as MASK",
         "a shadow map keeps one depth per texel, no partial coverage: a glTF material with alphaMode BLEND "
         "casts where its alpha is at least 0.5 and not elsewhere, in the maps, the GPU pass and the reference"},
        {alpha_texture_missing, F, "alpha texture missing",
         "an alpha-tested material's texture names a file that is not beside the model (textures left behind): "
         "its casters are opaque, in the maps, the GPU pass and the reference"},
        {base_colour_texture_missing, F, "base colour texture missing",
         "a material's base colour texture is not beside the model, not a PNG image ShadowLab reads, or on "
         "other texture coordinates: the Camera view shows that material's base colour factor alone"},
        {light_without_size, F, "a light without size",
         "PCSS sizes penumbrae by the light's radius or angular radius, here 0: hard shadows"},
        {search_clamped, F, "blocker search clamped",
         "PCSS's search reached its texel limit: blockers farther across the light are missed"},
        {open_mesh, L, "open or non-manifold mesh", "two-sided volumes, silhouette edges with multiplicity"},
        {eye_in_volume, L, "eye inside a shadow volume", "z-pass counts are wrong there; z-fail holds"},
        {no_eye_point, L, "no eye point",
         "the stencil count rasterizes the volumes from the camera's eye, which an orthographic camera lacks: "
         "nothing is counted and every pixel is lit; a map method or planar shadows serve this camera"},
        {not_planar_receiver, L, "only planar receivers", "planar shadows fall on planes only"},
        {below_plane, L, "casters below the plane", "they throw false shadows onto it"},
        {beyond_light, L, "casters beyond the light", "clipped at w = 0, else they throw anti-shadows"},
        {alpha_tested_whole, L, "alpha-tested casters drawn whole",
         "a technique's polygons carry no texture: alpha-tested casters (glTF MASK, OBJ map_d) cast through their "
         "holes too; a map method tests their alpha"},
        {missed_receivers, L, "visible receivers outside the maps",
         "no map's [0,1]^3 holds them: their shadows are lost, they read as lit"},
        {casters_before_near_plane, L, "casters before the near plane",
         "inside a map's (u, v) square but at d < 0: an engine that clips them loses their shadows (ShadowLab clamps "
         "them to depth 0, as depth clamping does)"},
        {texels_outside_view, L, "texels outside the view",
         "more than half of the maps' texels see no point of the view frustum's part of the scene"},
    };
    return kinds;
}

const NoteInfo& info(NoteKind kind) {
    for (const NoteInfo& i : all_note_kinds())
        if (i.kind == kind) return i;
    throw std::logic_error("a note kind missing from all_note_kinds()");
}

const char* to_string(NoteKind kind) { return info(kind).name; }

std::string describe(const Note& note) { return std::string(to_string(note.kind)) + ": " + note.message; }

std::string describe(const std::vector<Note>& notes) {
    std::string text;
    for (const Note& note : notes) text += (text.empty() ? "" : "; ") + describe(note);
    return text;
}

}  // namespace shadowlab
