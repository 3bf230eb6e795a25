// An engine's light view-projections as ShadowLab maps: each clip_from_world read from the file
// (io/matrix_import.hpp) becomes world_to_uvz = uvz_from_clip * clip_from_world under the engine's
// conventions (maps/clip_conventions.hpp); then every view, the measure and the coverage report
// apply to them as to ShadowLab's own.
#include "methods/custom.hpp"

#include "methods/engine_conventions.hpp"
#include "io/matrix_import.hpp"
#include "maps/clip_conventions.hpp"
#include "methods/focused.hpp"
#include "methods/light_fit.hpp"
#include "methods/map_coverage.hpp"
#include "methods/map_fit.hpp"
#include "methods/step_figures.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {
namespace {

ClipConventions conventions_of(const Settings& s) {
    return {.depth = clip_depth_of(s),
            .reversed_z = reversed_z_of(s),
            .v = s.choice("v_direction") == "down" ? TextureV::down : TextureV::up};
}

// One map serves every point; several lie in their tiles, chosen by the view depth when split
// depths are given (cascades), else by the first tile whose (u, v) holds the point.
MapSelection selection_of(const ShadowInputs& in, const EngineMatrices& engine) {
    if (!engine.split_depths.empty())
        return {.rule = MapSelection::Rule::view_depth,
                .eye = in.camera.position,
                .view_axis = in.camera.view_direction(),
                .split_depths = engine.split_depths};
    return {.rule = engine.clip_from_world.size() > 1 ? MapSelection::Rule::tile_bounds : MapSelection::Rule::only};
}

ShadowSetup converted(const ShadowInputs& in, const EngineMatrices& engine, const glm::dmat4& uvz_from_clip) {
    ShadowSetup setup{.selection = selection_of(in, engine)};
    const glm::dvec3 centre = in.scene_bounds.center();
    for (size_t k = 0; k < engine.clip_from_world.size(); ++k) {
        const glm::dmat4 world_to_uvz = uvz_from_clip * engine.clip_from_world[k];
        setup.maps.push_back(
            {.world_to_uvz = world_to_uvz,
             .viewport = engine.tiles.empty() ? glm::dvec4(0.0, 0.0, 1.0, 1.0) : engine.tiles[k],
             // reported and exported only: the depth per world unit along the light at the scene's centre
             .z_bias_scale = depth_slope_along(world_to_uvz, light_ray_at(in.light, centre), centre)});
    }
    return setup;
}

void record_conversion(const ShadowInputs& in, const Settings& s, const EngineMatrices& engine,
                       const glm::dmat4& uvz_from_clip, const ShadowSetup& setup, Trace* trace) {
    record(trace, [&](Trace& t) {
        Step& step = t.add("custom-conversion", "Engine matrices to world_to_uvz",
                           "world_to_uvz = uvz_from_clip * clip_from_world: clip x, y in [-1, 1] onto u, v in [0, 1], "
                           "the engine's depth onto d in [0, 1] growing away from the light",
                           Space::world)
                         .value("file", s.text("matrices"))
                         .value("storage", s.choice("storage"))
                         .value("clip_depth", s.choice("clip_depth"))
                         .value("reversed_z", s.choice("reversed_z"))
                         .value("v_direction", s.choice("v_direction"))
                         .value("uvz_from_clip", uvz_from_clip);
        for (size_t k = 0; k < setup.maps.size(); ++k) {
            // Appended, not prefixed: GCC 12 warns falsely of overlap (-Wrestrict) in `"x" + std::string`.
            const std::string suffix = setup.maps.size() > 1 ? std::string(" ").append(std::to_string(k)) : "";
            step.value("clip_from_world" + suffix, engine.clip_from_world[k])
                .value("world_to_uvz" + suffix, setup.maps[k].world_to_uvz)
                .map_shape(int(k), "map" + suffix, map_volume(setup.maps[k]), Role::map);
        }
        draw_light(step, in.light, in.scene_bounds.center(), 0.25 * in.scene_bounds.diagonal());
    });
}

void record_coverage(const ShadowInputs& in, const MapCoverage& c, Trace* trace) {
    record(trace, [&](Trace& t) {
        Step& step = t.add("custom-coverage", "Coverage of the view",
                           "visible receivers outside every map's [0,1]^3; casters in a map's (u, v) square at d < 0; "
                           "texels whose (u, v) sees no point of frustum ∩ scene",
                           Space::world)
                         .value("receiver_points", double(c.receiver_points.size()))
                         .value("missed_receiver_points", double(c.missed_points.size()))
                         .value("casters_before_near_plane", double(c.clipped_casters))
                         .value("texels_outside_view", c.texels_outside_view)
                         .shape("F", in.frustum, Role::view);
        if (!c.receiver_points.empty()) step.shape("visible receivers", PointSet{c.receiver_points}, Role::receivers);
        if (!c.missed_points.empty()) step.shape("missed receivers", PointSet{c.missed_points});
        if (!c.clipped_points.empty())
            step.shape("casters before the near plane", PointSet{c.clipped_points}, Role::casters);
    });
}

}  // namespace

std::vector<SettingSpec> custom_settings() {
    return {
        {.name = "matrices",
         .description = "the engine's light view-projections: a GLSL, HLSL or JSON file (README: Debugging your "
                        "engine)",
         .default_value = "",
         .is_text = true},
        storage_setting(),
        clip_depth_setting(),
        reversed_z_setting(),
        {.name = "v_direction",
         .description = "the texture's v: up, v = (1 + y) / 2 (OpenGL, Vulkan), or down, v = (1 - y) / 2 (Direct3D)",
         .default_value = "up",
         .choices = {"up", "down"}}};
}

ShadowSetup compute_custom(const ShadowInputs& in, const Settings& settings, Trace* trace) {
    const std::string& file = settings.text("matrices");
    if (file.empty()) {  // what a fit to the view gives: the focused map, its body by the default kernel
        ShadowSetup setup = compute_focused(in, resolve_settings("custom", {body_kernel_setting()}, {}), trace);
        setup.fallbacks.insert(setup.fallbacks.begin(),
                               Note{NoteKind::no_matrices, "set matrices=FILE (GLSL, HLSL or JSON); focused map used"});
        return setup;
    }
    const EngineMatrices engine = read_engine_matrices(file, storage_of(settings));
    const glm::dmat4 conversion = uvz_from_clip(conventions_of(settings));
    ShadowSetup setup = converted(in, engine, conversion);
    record_conversion(in, settings, engine, conversion, setup, trace);
    const MapCoverage coverage = map_coverage(in, setup);
    for (Note& note : coverage_notes(coverage)) add_fallback(setup, std::move(note));
    record_coverage(in, coverage, trace);
    record_output(setup, coverage.receiver_points, trace);
    return setup;
}

}  // namespace shadowlab
