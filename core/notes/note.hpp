#pragma once
// What a method or technique tells the user about its result, typed: a fallback (a degradation it
// took: another map, a clamp) or a limit (what a geometric technique cannot get right here). Every
// kind is listed once, with its name and meaning, in note.cpp; the CLI, the window and the tests
// compare kinds and show the name with the particulars.
#include <string>
#include <vector>

namespace shadowlab {

enum class NoteCategory { fallback, limit };

enum class NoteKind {
    // Fallbacks of the map methods.
    empty_scene,
    empty_body,
    behind_light,
    outside_cone,
    not_directional,
    nothing_to_warp,
    miners_lamp,
    empty_focus_region,
    parallel_light,
    degenerate_centre_line,
    focus_out_of_range,
    no_visible_receiver,
    no_depth_image,
    directional_light,
    margin_reduced,
    view_outside_cone,
    light_on_region,
    warp_not_needed,
    log_range_short,
    no_light_axis,
    no_matrices,
    orthographic_camera,
    over_page_budget,
    outside_clipmap,
    // Found when a warp is measured against the reference.
    warp_loses,
    // Fallbacks of the analyses drawn beside a method (the flatland plane).
    light_along_view,
    // Fallbacks of the scene's loading.
    blend_read_as_mask,
    alpha_texture_missing,
    base_colour_texture_missing,
    // Fallbacks of the lookups' filters.
    light_without_size,
    search_clamped,
    // Limits of the geometric techniques (shadow volumes, planar projection).
    open_mesh,
    eye_in_volume,
    no_eye_point,
    not_planar_receiver,
    below_plane,
    beyond_light,
    alpha_tested_whole,
    // Limits of maps an engine computed (the custom method's coverage report).
    missed_receivers,
    casters_before_near_plane,
    texels_outside_view,
};

struct Note {
    NoteKind kind;
    std::string message;  // the particulars: counts, names, what was used instead
};

struct NoteInfo {
    NoteKind kind;
    NoteCategory category;
    const char* name;     // as users read it: "empty intersection body"
    const char* meaning;  // one line: when it happens and what follows
};

const std::vector<NoteInfo>& all_note_kinds();
const NoteInfo& info(NoteKind kind);
const char* to_string(NoteKind kind);  // info(kind).name

// "name: message"; several notes joined by "; ", each starting with its name. Empty for none.
std::string describe(const Note& note);
std::string describe(const std::vector<Note>& notes);

}  // namespace shadowlab
