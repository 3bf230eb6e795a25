#pragma once
// Every fallback a method can take, by name. A setup's fallback text starts with one of these
// names, then ": " and the particulars, so the CLI, the GUI and the tests can tell them apart.
#include <array>
#include <string>

namespace shadowlab::fallback {

inline constexpr const char* empty_scene = "empty scene";
inline constexpr const char* empty_body = "empty intersection body";
inline constexpr const char* behind_light = "points behind the light";
inline constexpr const char* outside_cone = "points outside the light's cone";
inline constexpr const char* not_directional = "not a directional light";
inline constexpr const char* nothing_to_warp = "no caster can shadow a visible receiver";
inline constexpr const char* miners_lamp = "miner's lamp";
inline constexpr const char* empty_focus_region = "empty focus region";
inline constexpr const char* parallel_light = "light parallel to the view";
inline constexpr const char* degenerate_centre_line = "degenerate centre line";
inline constexpr const char* focus_out_of_range = "focus point out of the 80% rule's range";
// Shadow volumes and planar projection shadows (not shadow maps): limits met, each named.
inline constexpr const char* open_mesh = "open or non-manifold mesh";
inline constexpr const char* eye_in_volume = "eye inside a shadow volume";
inline constexpr const char* not_planar_receiver = "only planar receivers";
inline constexpr const char* below_plane = "casters below the plane";
inline constexpr const char* beyond_light = "casters beyond the light";

inline constexpr std::array all{empty_scene, empty_body, behind_light, outside_cone, not_directional,
                                nothing_to_warp, miners_lamp, empty_focus_region, parallel_light,
                                degenerate_centre_line, focus_out_of_range, open_mesh, eye_in_volume,
                                not_planar_receiver, below_plane, beyond_light};

// "name: details"; several limits met at once are joined by "; ", each starting with its name.
inline std::string named(const char* name, const std::string& details) { return std::string(name) + ": " + details; }

inline bool is_named(const std::string& text) {
    for (const char* name : all)
        if (text.rfind(name, 0) == 0) return true;
    return false;
}

}  // namespace shadowlab::fallback
