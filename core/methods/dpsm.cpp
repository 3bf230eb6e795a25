// Dual-paraboloid shadow maps. A point p seen from the light's centre c in a hemisphere's frame,
// q = frame_from_world (p - c), has the unit direction d = q / |q|; the paraboloid
// z = 1/2 - (x² + y²)/2 reflects d into the frame's +z, which puts it on the disc at
// (u, v) = (d.x, d.y) / (1 + d.z); its depth is the distance, (|q| - n) / (f - n), linear (no
// perspective divide). The back hemisphere is the same map in a frame turned half a turn about y,
// so one formula serves both: seed 002's listing normalizes a vector before assigning it and tests
// z < 0 in both lookup branches; maps/map_lookup.cpp implements the mapping as above.
//
// A GPU projects the vertices and joins them by straight edges, while the true image of a straight
// edge is a curve: `tessellate` splits the casters until no edge bows more than that many texels.
#include "methods/dpsm.hpp"

#include <cmath>
#include <numbers>

#include "math/matrix.hpp"
#include "methods/cascade_atlas.hpp"
#include "methods/focused.hpp"
#include "methods/light_fit.hpp"
#include "methods/map_fit.hpp"
#include "methods/omni_light.hpp"
#include "methods/step_figures.hpp"
#include "methods/tessellate_setting.hpp"

namespace shadowlab {
namespace {

// The frame whose +z is `axis` (the front hemisphere's), x and y completing it right-handed.
glm::dmat3 frame_from_world_along(const glm::dvec3& axis) {
    const glm::dvec3 z = glm::normalize(axis);
    const glm::dvec3 hint = std::abs(z.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 x = glm::normalize(glm::cross(hint, z)), y = glm::cross(z, x);
    return glm::transpose(glm::dmat3(x, y, z));  // rows x, y, z
}

// Turned half a turn about the frame's y: x and z change sign.
glm::dmat3 turned_half_about_y(const glm::dmat3& frame_from_world) {
    const glm::dmat3 half_turn_about_y(glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, -1));
    return half_turn_about_y * frame_from_world;
}

glm::dvec3 front_axis(const ShadowInputs& in, const Settings& s) {
    if (s.choice("axis") == "view") return in.camera.view_direction();
    if (in.light.type == LightType::spot && s.choice("axis") == "spot") return in.light.direction;
    return {0.0, -1.0, 0.0};  // down: the seam runs level through the light
}

ShadowMap hemisphere(const glm::dvec3& centre, const glm::dmat3& frame_from_world, const LightRange& range,
                     double max_sagitta_texels, const AtlasTile& tile) {
    return {
        .projection = Projection::paraboloid,
        .paraboloid = {.centre = centre, .frame_from_world = frame_from_world, .near = range.near, .far = range.far},
        .viewport = tile_viewport(tile),
        .z_bias_scale = 1.0 / (range.far - range.near),  // d grows by 1 / (f - n) per unit of distance
        .max_sagitta_texels = max_sagitta_texels};
}

// ---- steps ----

glm::dmat4 light_from_world_of(const Paraboloid& p) {
    glm::dmat4 m(p.frame_from_world);
    m[3] = glm::dvec4(-(p.frame_from_world * p.centre), 1.0);
    return m;
}

// The disc of hemisphere i in the atlas, its rim (ρ = 1: the seam) drawn at depth 0.
std::vector<glm::dvec4> atlas_disc(const ShadowMap& map) {
    const glm::dvec4 vp = map.viewport;
    const glm::dvec2 centre{(vp.x + vp.z) / 2, (vp.y + vp.w) / 2};
    const double radius = (vp.z - vp.x) / 2;
    std::vector<glm::dvec4> rim;
    for (int k = 0; k < 96; ++k) {
        const double t = 2 * std::numbers::pi * k / 96;
        rim.emplace_back(centre + radius * glm::dvec2(std::cos(t), std::sin(t)), 0.0, 1.0);
    }
    return rim;
}

// The points on the map's side of the split plane (its hemisphere's).
std::vector<glm::dvec3> on_side_of(const ShadowMap& map, const std::vector<glm::dvec3>& ws_points) {
    std::vector<glm::dvec3> side;
    for (const glm::dvec3& p : ws_points)
        if (hemisphere_side(map, p) >= 0.0) side.push_back(p);
    return side;
}

// A point's place in the atlas: its hemisphere's (u, v) through the tile, on the discs' plane.
glm::dvec3 atlas_point(const ShadowMap& map, const glm::dvec3& world) {
    return {texture_uv(map, glm::dvec2(world_to_uvz(map, world))), 0.0};
}

void record_steps(Trace& t, const ShadowInputs& in, const ShadowSetup& setup, const LightRange& range) {
    const Paraboloid& front = setup.maps[0].paraboloid;
    const glm::dmat4 light_from_world = light_from_world_of(front);
    t.set_frame(Space::light, light_from_world);
    const std::vector<glm::dvec3> ws_casters = in.caster_points();
    const double arm = range.far / 4;

    // In the world: the frame's axes at the light, and the split plane between the hemispheres.
    const glm::dmat3 world_from_frame = glm::transpose(front.frame_from_world);
    Step& frame = t.add("dpsm-frame", "The paraboloids' frame",
                        "front hemisphere: +z of the frame at the light; back: the frame turned half a turn about y; "
                        "the split plane between them is the seam",
                        Space::world)
                      .value("centre", front.centre)
                      .value("frame_from_world", glm::dmat4(front.frame_from_world));
    for (const auto& [name, axis] : {std::pair{"x", glm::dvec3(1, 0, 0)}, std::pair{"y", glm::dvec3(0, 1, 0)},
                                     std::pair{"z (front)", glm::dvec3(0, 0, 1)}})
        draw_arrow(frame, name, front.centre, world_from_frame * axis, arm, Role::light);
    std::vector<glm::dvec4> ws_split_plane;
    for (const glm::dvec2& corner : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)})
        ws_split_plane.emplace_back(front.centre + arm * (world_from_frame * glm::dvec3(corner, 0.0)), 1.0);
    frame.shape("split plane", PolygonSet{}.add(ws_split_plane), Role::map)
        .shape("casters", PointSet{ws_casters}, Role::casters);

    std::vector<glm::dvec3> ls_directions;
    for (const glm::dvec3& ls : transformed(ws_casters, light_from_world))
        if (glm::length(ls) > 0.0) ls_directions.push_back(arm * glm::normalize(ls));
    t.add("dpsm-normalize", "Normalize", "d = q / |q|: each point's direction from the light (drawn at radius f/4)",
          Space::light)
        .value("radius_drawn", arm)
        .shape("d", PointSet{ls_directions}, Role::focus)
        .shape("casters", PointSet{transformed(ws_casters, light_from_world)}, Role::casters);

    Step& projection =
        t.add("dpsm-project", "Project onto the disc",
              "(u, v) = (d.x, d.y) / (1 + d.z), then onto the hemisphere's tile: a disc of radius 1", Space::unit);
    for (size_t i = 0; i < setup.maps.size(); ++i) {
        std::vector<glm::dvec3> on_disc;
        for (const glm::dvec3& p : on_side_of(setup.maps[i], ws_casters))
            on_disc.push_back(atlas_point(setup.maps[i], p));
        const std::string name = i == 0 ? "front" : "back";
        projection.map_shape(int(i), name + " disc", PolygonSet{}.add(atlas_disc(setup.maps[i])), Role::map)
            .map_shape(int(i), name + " label", Label{{setup.maps[i].viewport.x, setup.maps[i].viewport.w, 0.0}, name});
        if (!on_disc.empty()) projection.map_shape(int(i), name + " casters", PointSet{on_disc});
    }

    Step& depth = t.add("dpsm-depth", "Depth: the distance",
                        "d = (|q| - n) / (f - n): linear in the distance, no perspective divide", Space::light)
                      .value("n", range.near)
                      .value("f", range.far)
                      .value("z_bias_scale", setup.maps[0].z_bias_scale);
    draw_dimension(depth, "f", glm::dvec3(0.0), glm::dvec3(range.far, 0.0, 0.0));
    depth.shape("casters", PointSet{transformed(ws_casters, light_from_world)}, Role::casters);

    Step& choice = t.add("dpsm-hemisphere", "Choose the hemisphere",
                         "a point reads the front map where its z >= 0 in the frame, else the back map", Space::light);
    for (size_t i = 0; i < setup.maps.size(); ++i) {
        const std::vector<glm::dvec3> side = transformed(on_side_of(setup.maps[i], ws_casters), light_from_world);
        if (!side.empty()) choice.map_shape(int(i), i == 0 ? "front points" : "back points", PointSet{side});
    }
    choice.shape("split plane",
                 PolygonSet{}.add({{-arm, -arm, 0, 1}, {arm, -arm, 0, 1}, {arm, arm, 0, 1}, {-arm, arm, 0, 1}}),
                 Role::map);

    // Solid angle per texel ∝ 4 / (1 + ρ²)²: 4 at the disc's centre, 1 at its rim.
    Step& seam = t.add("dpsm-seam", "The seam",
                       "the rim (ρ = 1) of both discs is the split plane: texels there see a quarter of the solid "
                       "angle of those at the centre (4 / (1 + ρ²)²), and neighbours across it lie in two tiles",
                       Space::unit)
                     .value("solid_angle_centre", 4.0)
                     .value("solid_angle_rim", 1.0);
    for (size_t i = 0; i < setup.maps.size(); ++i)
        seam.map_shape(int(i), "rim " + std::to_string(i), PolygonSet{}.add(atlas_disc(setup.maps[i])), Role::step);
}

}  // namespace

ShadowSetup compute_dpsm(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    if (!omni_or_focused("dpsm", in, s, setup, trace)) return setup;
    const LightRange range = omni_range(in);
    const glm::dmat3 front = frame_from_world_along(front_axis(in, s));
    const std::vector<AtlasTile> tiles = atlas_layout(2, {});
    const double max_sagitta = s.number("tessellate");
    setup.maps = {hemisphere(in.light.position, front, range, max_sagitta, tiles[0]),
                  hemisphere(in.light.position, turned_half_about_y(front), range, max_sagitta, tiles[1])};
    setup.selection = {.rule = MapSelection::Rule::hemisphere};
    record(trace, [&](Trace& t) {
        record_range(t, in.light, range, !in.light.range);
        record_steps(t, in, setup, range);
    });
    record_output(setup, in.caster_points(), trace);
    return setup;
}

std::vector<SettingSpec> dpsm_settings() {
    return {{.name = "axis",
             .description = "the front hemisphere's axis: down (the seam level through the light), the view "
                            "direction, or a spot light's axis",
             .default_value = "down",
             .choices = {"down", "view", "spot"}},
            tessellate_setting("0"),
            body_kernel_setting()};
}

}  // namespace shadowlab
