// Cascaded shadow maps (Engel 2006; Zhang et al. 2006, parallel-split shadow maps): the
// view frustum cut into slices along the view depth, each slice given its own map fit to its part of
// the intersection body, all maps tiles of one texture. Near slices are short, so their maps spend
// their texels on little ground: the perspective aliasing a single map has, shared out by slice.
#include "methods/cascades.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "geometry/intersection_body.hpp"
#include "math/matrix.hpp"
#include "methods/cascade_atlas.hpp"
#include "methods/cascade_fit.hpp"
#include "methods/cascade_splits.hpp"
#include "methods/focused.hpp"
#include "methods/light_fit.hpp"
#include "methods/lispsm.hpp"
#include "methods/map_fit.hpp"
#include "methods/step_figures.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {
namespace {

enum class FitKind { cascade, scene, sphere };

// The settings, read and checked against each other and the camera.
struct CascadeOptions {
    int count = 4;
    bool visible_bounds = false;  // the depths split are the visible receivers' (bounds = visible, measured)
    std::vector<double> depths;   // count + 1 split depths across the bounds
    FitKind fit = FitKind::cascade;
    bool stabilize = false;
    bool lispsm = false;
    double blend = 0.0;
    bool by_tile = false;
    std::vector<AtlasTile> tiles;  // one per cascade
};

[[noreturn]] void refuse(const std::string& setting, const std::string& value, const std::string& why) {
    throw std::invalid_argument("method cascades: setting " + setting + "=" + value + ": " + why);
}

// The depths the cascades cover: the camera's near plane to the shadow distance (`far`, 0: the
// camera's far); with bounds = visible, narrowed to the receivers the camera's depth image shows
// (SDSM), or a named fallback to the frustum's when there are none or no image was measured.
DepthRange depth_bounds(const ShadowInputs& in, const Settings& s, std::vector<Note>& fallbacks) {
    const Camera& camera = in.camera;
    const double shadow_distance = s.number("far") > 0.0 ? std::min(s.number("far"), camera.far) : camera.far;
    if (shadow_distance <= camera.near)
        refuse("far", label_number(s.number("far")), "below the camera's near plane " + label_number(camera.near));
    const DepthRange frustum{.near = camera.near, .far = shadow_distance};
    if (!cascades_read_visible_depths(s)) return frustum;
    const std::optional<DepthRange>& seen = in.visible_depths;
    if (!seen) {
        fallbacks.push_back({NoteKind::no_depth_image, "cascades from the camera's near plane to the shadow distance"});
        return frustum;
    }
    const DepthRange visible{.near = std::max(seen->near, frustum.near), .far = std::min(seen->far, frustum.far)};
    if (visible.empty()) {
        fallbacks.push_back({NoteKind::no_visible_receiver,
                             seen->empty() ? "the camera sees none" : "none nearer than the shadow distance"});
        return frustum;
    }
    return visible;
}

// The split depths across the bounds: PSSM's practical scheme, or the manual fractions.
std::vector<double> split_depths(const Settings& s, const DepthRange& bounds, int count) {
    if (s.choice("scheme") == "practical") return practical_splits(bounds.near, bounds.far, count, s.number("lambda"));
    const std::vector<double> fractions = s.numbers("splits");
    if (int(fractions.size()) != count - 1)
        refuse("splits", s.choice("splits"),
               std::to_string(count - 1) + " fractions needed for count=" + std::to_string(count));
    for (size_t i = 0; i < fractions.size(); ++i)
        if (!(fractions[i] > (i == 0 ? 0.0 : fractions[i - 1]) && fractions[i] < 1.0))
            refuse("splits", s.choice("splits"), "fractions of the depth range must increase within (0, 1)");
    return manual_splits(bounds.near, bounds.far, fractions);
}

// The atlas: tiles of the relative sides asked for (the resolution per cascade), none below the smallest.
std::vector<AtlasTile> atlas_tiles(const Settings& s, int count) {
    const std::vector<double> sides = s.numbers("tiles");
    if (!sides.empty() && int(sides.size()) != count)
        refuse("tiles", s.choice("tiles"), std::to_string(count) + " sides needed for count=" + std::to_string(count));
    for (double side : sides)
        if (side != std::exp2(std::round(std::log2(side))))
            refuse("tiles", s.choice("tiles"), "each side must be 1, 0.5, 0.25 or 0.125 of the largest");
    std::vector<AtlasTile> tiles = atlas_layout(count, sides);
    const double smallest =
        std::min_element(tiles.begin(), tiles.end(), [](auto& a, auto& b) { return a.side < b.side; })->side;
    if (smallest < kMinTileSide)
        refuse("tiles", s.choice("tiles"),
               "more tiles than fit the atlas: the smallest would be 1/" + label_number(1 / smallest) +
                   " of its side (at least 1/" + label_number(1 / kMinTileSide) + ")");
    return tiles;
}

CascadeOptions read_options(const Settings& s, const ShadowInputs& in, std::vector<Note>& fallbacks) {
    const double count = s.number("count");
    if (count != std::round(count)) refuse("count", label_number(count), "expected a whole number");
    CascadeOptions o{.count = int(count),
                     .fit = s.choice("fit") == "scene"    ? FitKind::scene
                            : s.choice("fit") == "sphere" ? FitKind::sphere
                                                          : FitKind::cascade,
                     .stabilize = s.choice("stabilize") == "on",
                     .lispsm = s.choice("warp") == "lispsm",
                     .blend = s.number("blend"),
                     .by_tile = s.choice("select") == "tile"};
    // A warp follows the camera: there is no still box to snap, nor one whose bounds a tile test could read.
    if (o.lispsm && o.stabilize) refuse("stabilize", "on", "a LiSPSM warp moves with the camera (use warp=none)");
    if (o.lispsm && o.by_tile) refuse("select", "tile", "tile bounds need the light-space boxes (use warp=none)");
    if (o.lispsm && in.camera.is_orthographic()) {
        o.lispsm = false;
        fallbacks.push_back(Note{NoteKind::orthographic_camera,
                                 "cascades' LiSPSM warp: the camera is orthographic, nothing to warp; box fits used"});
    }
    const size_t fallbacks_before = fallbacks.size();
    const DepthRange bounds = depth_bounds(in, s, fallbacks);
    o.visible_bounds = cascades_read_visible_depths(s) && fallbacks.size() == fallbacks_before;
    o.depths = split_depths(s, bounds, o.count);
    o.tiles = atlas_tiles(s, o.count);
    return o;
}

// One cascade as its steps show it.
struct Cascade {
    double near = 0.0, far = 0.0;       // the view depths its map covers (the blend band and `fit` included)
    Frustum slice;                      // the view frustum between them
    IntersectionBody part;              // the slice's part of the scene and what can shadow it
    std::vector<glm::dvec3> ws_cover;   // the points its map must hold: the part, or the slice when it is empty
    std::optional<Sphere> sphere;       // fit = sphere
    Aabb ls_fit;                        // the light-space box fit, before any snap
    std::optional<SnappedBox> snapped;  // stabilize
    std::optional<LispsmWarp> warp;     // warp = lispsm, when it warps
    AtlasTile tile;
    ShadowMap map;
};

// The depths cascade i serves: its split, reaching back over the band where the previous one
// crossfades into it; fit = scene reaches back to the near plane (as the DirectX SDK sample's
// "fit to scene").
std::pair<double, double> covered_depths(const CascadeOptions& o, int i) {
    const std::vector<double>& d = o.depths;
    if (o.fit == FitKind::scene) return {d.front(), d[i + 1]};
    return {i == 0 ? d[0] : d[i] - o.blend * (d[i] - d[i - 1]), d[i + 1]};
}

// The light box around what the cascade must cover: a tight box, or the slice's sphere (its x, y);
// spanning the scene's depth for the tile test (a tile that holds a point's (u, v) then holds its depth);
// snapped to the texel grid to stabilize.
void fit_light_box(const ShadowInputs& in, const CascadeOptions& o, const glm::dmat4& light_from_world, Cascade& c) {
    c.ls_fit = bounds_of(transformed(c.ws_cover, light_from_world));
    if (c.sphere) {
        const glm::dvec3 ls_centre = transform_point(light_from_world, c.sphere->centre);
        const double radius =
            o.stabilize ? quantize_up(c.sphere->radius, in.scene_bounds.diagonal()) : c.sphere->radius;
        c.ls_fit.min = {ls_centre.x - radius, ls_centre.y - radius, c.ls_fit.min.z};
        c.ls_fit.max = {ls_centre.x + radius, ls_centre.y + radius, c.ls_fit.max.z};
    }
    if (o.by_tile) {
        const Aabb ls_scene = transformed(in.scene_bounds, light_from_world);
        c.ls_fit.min.z = ls_scene.min.z;
        c.ls_fit.max.z = ls_scene.max.z;
    }
    if (o.stabilize) c.snapped = snap_to_texels(c.ls_fit, in.scene_bounds.diagonal());
}

Cascade build_cascade(const ShadowInputs& in, const CascadeOptions& o, BodyKernel kernel,
                      const glm::dmat4& light_from_world, int i) {
    Cascade c;
    std::tie(c.near, c.far) = covered_depths(o, i);
    c.slice = depth_slice(in.camera, c.near, c.far);
    c.part = intersection_body({c.slice, in.scene_bounds, in.light.homogeneous()}, kernel);
    c.ws_cover = c.part.body.empty() ? std::vector<glm::dvec3>(c.slice.corners.begin(), c.slice.corners.end())
                                     : c.part.body.vertices;
    if (o.fit == FitKind::sphere) c.sphere = slice_sphere(in.camera, c.near, c.far);
    c.tile = o.tiles[i];
    if (o.lispsm) {
        LispsmWarp warp = lispsm_warp({.ws_body = &c.ws_cover,
                                       .eye = in.camera.position,
                                       .view_direction = in.camera.view_direction(),
                                       .light_direction = in.light.direction,
                                       .z_n = c.near});
        if (warp.warps) c.warp = std::move(warp);
    }
    if (c.warp) {
        c.map = c.warp->map;
    } else {
        fit_light_box(in, o, light_from_world, c);
        c.map = orthographic_map(light_from_world, c.snapped ? c.snapped->box : c.ls_fit);
    }
    c.map.viewport = tile_viewport(c.tile);
    return c;
}

MapSelection selection_of(const ShadowInputs& in, const CascadeOptions& o) {
    if (o.by_tile) return {.rule = MapSelection::Rule::tile_bounds};
    return {.rule = MapSelection::Rule::view_depth,
            .eye = in.camera.position,
            .view_axis = in.camera.view_direction(),
            .split_depths = o.depths,
            .blend_band = o.blend};
}

// ---- steps ----

// A slice's face at view depth `depth`, as a polygon to fill.
std::vector<glm::dvec4> depth_face(const Camera& camera, double depth) {
    const Frustum f = depth_slice(camera, depth, 2 * depth);
    return {glm::dvec4(f.corners[0], 1), glm::dvec4(f.corners[1], 1), glm::dvec4(f.corners[2], 1),
            glm::dvec4(f.corners[3], 1)};
}

// SDSM's bounds: the frustum's depth range against the part of it the camera sees receivers in.
void record_visible_bounds(Trace& t, const ShadowInputs& in, const CascadeOptions& o) {
    const double z_min = o.depths.front(), z_max = o.depths.back();
    Step& step = t.add("cascade-bounds", "Visible depth bounds",
                       "the nearest and farthest receiver in the camera's depth image (sample distribution shadow "
                       "maps): the splits span these, not the frustum's near to far",
                       Space::world)
                     .value("z_min", z_min)
                     .value("z_max", z_max)
                     .value("frustum_near", in.camera.near)
                     .value("frustum_far", in.camera.far)
                     .shape("F", in.frustum, Role::view);
    for (const auto& [name, depth] : {std::pair{"z_min", z_min}, std::pair{"z_max", z_max}}) {
        const std::vector<glm::dvec4> face = depth_face(in.camera, depth);
        step.shape(name, PolygonSet{}.add(face), Role::focus)
            .shape(std::string(name) + " label",
                   Label{glm::dvec3(face[3]), std::string(name) + " = " + label_number(depth)}, Role::focus);
    }
}

void record_splits(Trace& t, const ShadowInputs& in, const Settings& s, const CascadeOptions& o) {
    const bool practical = s.choice("scheme") == "practical";
    Step& step = t.add("cascade-splits", "Split distances",
                       practical ? "C_i = λ n (f/n)^(i/m) + (1 - λ)(n + (f - n) i/m): λ = 1 logarithmic, 0 uniform"
                                 : "C_i = n + fraction_i (f - n)",
                       Space::world)
                     .value("n", o.depths.front())
                     .value("f", o.depths.back())
                     .value("m", double(o.count));
    if (practical) step.value("lambda", s.number("lambda"));
    step.shape("F", depth_slice(in.camera, o.depths.front(), o.depths.back()), Role::view);
    for (size_t i = 1; i + 1 < o.depths.size(); ++i) {
        const std::string name = "C_" + std::to_string(i);
        const std::vector<glm::dvec4> face = depth_face(in.camera, o.depths[i]);
        step.value(name, o.depths[i])
            .shape(name, PolygonSet{}.add(face))
            .shape(name + " label", Label{glm::dvec3(face[3]), name + " = " + label_number(o.depths[i])});
    }
}

// Cascade i's steps, numbered from 1 for people; its slice, box and tile drawn in its map's colour.
void record_cascade(Trace& t, const glm::dmat4& light_from_world, const Cascade& c, int i) {
    const std::string k = std::to_string(i + 1), id = "cascade-" + k, name = "cascade " + k;
    Step& slice = t.add(id, "Cascade " + k + ": slice and body",
                        "the view frustum between depths " + label_number(c.near) + " and " + label_number(c.far) +
                            "; its body: what can shadow the slice's part of the scene",
                        Space::world)
                      .value("near", c.near)
                      .value("far", c.far)
                      .value("body_volume", c.part.body.volume())
                      .map_shape(i, "slice " + k, c.slice, Role::view)
                      .map_shape(i, name + " label", Label{c.slice.corners[7], name});
    if (!c.part.body.empty()) slice.shape("B_" + k, c.part.body, Role::focus);

    if (c.warp) {
        Step& warp = t.add(id + "-warp", "Cascade " + k + ": LiSPSM warp",
                           "LiSPSM inside the slice: n = (z_n + sqrt(z_n z_f)) / sin γ with z_n = the slice's near",
                           Space::light)
                         .value("z_n", c.near)
                         .value("n", c.warp->n)
                         .value("P", c.warp->ppls_from_light)
                         .shape("B_" + k, PointSet{transformed(c.ws_cover, light_from_world)}, Role::focus);
        draw_warp_frustum(warp, *c.warp);
    } else {
        const Aabb& box = c.snapped ? c.snapped->box : c.ls_fit;
        Step& fit =
            t.add(id + "-fit", "Cascade " + k + ": light box",
                  c.sphere ? "x, y: the slice's bounding sphere, centre ± r (its size fixed as the camera turns)"
                           : "the light-space AABB of the slice's body",
                  Space::light)
                .value("min", box.min)
                .value("max", box.max)
                .shape("B_" + k, PointSet{transformed(c.ws_cover, light_from_world)}, Role::focus)
                .map_shape(i, "box " + k, box, Role::map)
                .map_shape(i, "box label", Label{box.max, name}, Role::map);
        if (c.sphere) {
            const glm::dvec3 ls_centre = transform_point(light_from_world, c.sphere->centre);
            std::vector<glm::dvec4> circle;
            for (int n = 0; n < 48; ++n) {
                const double a = 2 * std::numbers::pi * n / 48;
                circle.emplace_back(ls_centre + c.sphere->radius * glm::dvec3(std::cos(a), std::sin(a), 0), 1.0);
            }
            fit.value("radius", c.sphere->radius).shape("sphere", PolygonSet{}.add(circle));
        }
        if (c.snapped) {
            // The snap moves the box's corner by under one cell of extent / 256 onto the grid through the scene's
            // centre.
            const glm::dvec2 cell = glm::dvec2(c.snapped->box.extent()) / double(kSnapCells);
            fit.value("snap_offset_cells", c.snapped->offset_cells)
                .value("cell", cell)
                .shape("unsnapped", c.ls_fit)
                .shape("snap label", Label{c.snapped->box.min,
                                           "snapped by (" + label_number(c.snapped->offset_cells.x) + ", " +
                                               label_number(c.snapped->offset_cells.y) + ") cells of 1/256 tile"});
        }
    }

    const glm::dvec4 vp = c.map.viewport;
    Step& tile =
        t.add(id + "-tile", "Cascade " + k + ": its tile",
              "the tile matrix, NDC to texture (v down): x by s/2, y by -s/2, offset s/2 + s (column, row); s = " +
                  label_number(c.tile.side),
              Space::unit)
            .value("tile_matrix", atlas_tile_matrix(c.tile))
            .value("viewport", vp)
            .map_shape(i, "tile " + k, Aabb{{vp.x, vp.y, 0.0}, {vp.z, vp.w, 1.0}})
            .map_shape(i, "tile label", Label{{vp.x, vp.w, 1.0}, "tile " + k});
    draw_unit_cube(tile);
}

void record_selection(Trace& t, const ShadowInputs& in, const CascadeOptions& o, const ShadowSetup& setup) {
    if (o.by_tile) {
        Step& step = t.add("cascade-selection", "Selection by tile bounds",
                           "a point reads the first map whose (u, v) holds it", Space::world);
        for (size_t i = 0; i < setup.maps.size(); ++i) {
            const Frustum volume = map_volume(setup.maps[i]);
            const std::string name = "map " + std::to_string(i + 1);
            step.map_shape(int(i), name, volume, Role::map)
                .map_shape(int(i), name + " label", Label{volume.corners[6], name});
        }
        return;
    }
    Step& step = t.add("cascade-selection", "Selection by view depth",
                       "cascade i serves view depths [C_i-1, C_i); over the last " + label_number(100 * o.blend) +
                           "% of a split it crossfades into the next",
                       Space::world)
                     .value("blend_band", o.blend);
    for (size_t i = 0; i + 1 < o.depths.size(); ++i) {
        const std::vector<glm::dvec4> face = depth_face(in.camera, o.depths[i]);
        const std::string name = "cascade " + std::to_string(i + 1);
        step.map_shape(int(i), name + " from", PolygonSet{}.add(face))
            .map_shape(int(i), name + " label",
                       Label{glm::dvec3(face[2]),
                             name + ": [" + label_number(o.depths[i]) + ", " + label_number(o.depths[i + 1]) + ")"});
        if (i > 0 && o.blend > 0.0) {
            const double band_start = o.depths[i] - o.blend * (o.depths[i] - o.depths[i - 1]);
            step.shape(name + " blend", PolygonSet{}.add(depth_face(in.camera, band_start)), Role::map);
        }
    }
}

}  // namespace

ShadowSetup compute_cascades(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    const CascadeOptions o = read_options(s, in, setup.fallbacks);
    const auto body = start_warp("cascades", in, s, setup, trace);
    if (!body) return setup;

    // A light space that does not turn with the camera when stabilizing, its origin (where the snap grid
    // is anchored) the scene's centre: the grid moves with the scene, so a scene moved a million units
    // away is snapped as it was at home. Else y along the view, as focused.
    const glm::dmat4 light_from_world =
        o.stabilize ? light_basis(in.light.direction, stable_up_hint(in.light.direction), in.scene_bounds.center())
                          .light_from_world
                    : light_basis(in.light.direction, in.camera.view_direction()).light_from_world;
    const BodyKernel kernel = *body_kernel_from_string(s.choice("kernel"));
    std::vector<Cascade> cascades;
    for (int i = 0; i < o.count; ++i) {
        cascades.push_back(build_cascade(in, o, kernel, light_from_world, i));
        if (o.lispsm && !cascades.back().warp)
            add_fallback(
                setup, Note{NoteKind::parallel_light,
                            "cascade " + std::to_string(i + 1) + ": the warp has faded to nothing; its box fit used"});
        setup.maps.push_back(cascades.back().map);
    }
    setup.selection = selection_of(in, o);
    record(trace, [&](Trace& t) {
        t.set_frame(Space::light, light_from_world);
        if (const auto& warp = cascades.front().warp)
            t.set_frame(Space::ppls, warp->ppls_from_light * light_from_world);
        if (o.visible_bounds) record_visible_bounds(t, in, o);
        record_splits(t, in, s, o);
        for (int i = 0; i < o.count; ++i) record_cascade(t, light_from_world, cascades[i], i);
        record_selection(t, in, o, setup);
    });
    record_output(setup, body->body.vertices, trace);
    return setup;
}

std::vector<SettingSpec> cascades_settings() {
    return {
        {.name = "count",
         .description = "cascades (maps in the atlas)",
         .default_value = "4",
         .min = 1.0,
         .max = double(kMaxCascades)},
        {.name = "scheme",
         .description = "split depths: PSSM's practical formula or the manual fractions",
         .default_value = "practical",
         .choices = {"practical", "manual"}},
        {.name = "lambda",
         .description = "practical: λ, 1 logarithmic, 0 uniform",
         .default_value = "0.5",
         .min = 0.0,
         .max = 1.0},
        {.name = "splits",
         .description = "manual: the inner split depths as increasing fractions of the depth range",
         .default_value = "0.05,0.2,0.5",
         .min = 0.0,
         .max = 1.0,
         .is_list = true},
        {.name = "far",
         .description = "the shadow distance (depths beyond are lit); 0 = the camera's far",
         .default_value = "0",
         .min = 0.0,
         .max = 1e12,
         .length_power = 1},
        {.name = "bounds",
         .description = "the depths split: the camera's near to far, or the visible receivers' (its depth image)",
         .default_value = "frustum",
         .choices = {"frustum", "visible"}},
        {.name = "fit",
         .description = "each map around its slice's body, from the near plane (scene), or its sphere",
         .default_value = "cascade",
         .choices = {"cascade", "scene", "sphere"}},
        {.name = "stabilize",
         .description = "snap each light box to whole texels (and quantize the sphere)",
         .default_value = "off",
         .choices = {"on", "off"}},
        {.name = "warp",
         .description = "none, or LiSPSM inside each split",
         .default_value = "none",
         .choices = {"none", "lispsm"}},
        {.name = "blend",
         .description = "the share of each split over which it crossfades into the next",
         .default_value = "0",
         .min = 0.0,
         .max = 0.5},
        {.name = "select",
         .description = "a point's map: by view depth, or the first tile that holds it",
         .default_value = "depth",
         .choices = {"depth", "tile"}},
        {.name = "tiles",
         .description = "each cascade's tile side, 1, 0.5, 0.25 or 0.125 of the largest (its resolution); empty: equal",
         .default_value = "",
         .min = 0.125,
         .max = 1.0,
         .is_list = true},
        body_kernel_setting()};
}

bool cascades_read_visible_depths(const Settings& s) { return s.choice("bounds") == "visible"; }

}  // namespace shadowlab
