// Cube shadow maps: the sphere of directions around the light cut by the cube's six faces, each a
// perspective map with a 90° field of view (tangents from -1 to 1) looking along a world axis. The
// faces meet edge to edge, so every direction lands on exactly one face: the one of its major axis.
#include "methods/cube.hpp"

#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "methods/cascade_atlas.hpp"
#include "methods/focused.hpp"
#include "methods/light_fit.hpp"
#include "methods/map_fit.hpp"
#include "methods/omni_light.hpp"
#include "methods/step_figures.hpp"

namespace shadowlab {
namespace {

struct Face {
    const char* name;
    glm::dvec3 axis;
};
// +x, -x, +y, -y, +z, -z: in this order the face_axis rule's first on ties is the major axis's
// (x before y before z), as a GPU's cube map picks.
constexpr std::array<Face, 6> kFaces{{{"+x", {1, 0, 0}},
                                      {"-x", {-1, 0, 0}},
                                      {"+y", {0, 1, 0}},
                                      {"-y", {0, -1, 0}},
                                      {"+z", {0, 0, 1}},
                                      {"-z", {0, 0, -1}}}};

// The 3 x 2 atlas: faces +x, -x, +y in the top row, -y, +z, -z below, each a third of the side.
AtlasTile face_tile(int face) { return {.column = face % 3, .row = face / 3, .side = 1.0 / 3}; }

ShadowMap face_map(const Light& light, const LightRange& range, int face) {
    const glm::dvec3 axis = kFaces[face].axis;
    const glm::dvec3 up_hint = axis.y != 0.0 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    const glm::dmat4 light_from_world = light_basis(axis, up_hint, light.position).light_from_world;
    // A point at distance r from the light lies at least r / √3 along its face's axis (the major
    // axis of its direction): the faces' near plane at near / √3 keeps every point of the range.
    const double face_near = range.near / std::sqrt(3.0);
    ShadowMap map = perspective_map_of(light_from_world, Aabb{{-1.0, -1.0, face_near}, {1.0, 1.0, range.far}});
    map.projection = Projection::cube_face;
    map.cube_face = face;
    map.face_axis = axis;
    map.viewport = tile_viewport(face_tile(face));
    return map;
}

void record_faces(Trace& t, const ShadowSetup& setup) {
    for (int face = 0; face < 6; ++face) {
        const ShadowMap& map = setup.maps[face];
        const Frustum volume = map_volume(map);
        const std::string name = std::string("face ") + kFaces[face].name;
        t.add("cube-face-" + std::to_string(face), "Face " + std::string(kFaces[face].name),
              "a 90° perspective map along " + std::string(kFaces[face].name) +
                  ": tangents -1..1, depth f (z - n) / ((f - n) z)",
              Space::world)
            .value("world_to_uvz", map.world_to_uvz)
            .map_shape(face, name, volume, Role::map)
            .map_shape(face, name + " label", Label{volume.corners[6], name});
    }
    Step& atlas = t.add("cube-atlas", "The atlas",
                        "six faces of a third of the texture's side: +x, -x, +y over -y, +z, -z; a point reads the "
                        "face of the major axis of p - light",
                        Space::unit);
    for (int face = 0; face < 6; ++face) {
        const glm::dvec4 vp = setup.maps[face].viewport;
        atlas.map_shape(face, std::string("tile ") + kFaces[face].name, Aabb{{vp.x, vp.y, 0.0}, {vp.z, vp.w, 1.0}})
            .map_shape(face, std::string("tile label ") + kFaces[face].name,
                       Label{{vp.x, vp.w, 1.0}, kFaces[face].name});
    }
}

}  // namespace

ShadowSetup compute_cube(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    if (!omni_or_focused("cube", in, s, setup, trace)) return setup;
    const LightRange range = omni_range(in);
    for (int face = 0; face < 6; ++face) setup.maps.push_back(face_map(in.light, range, face));
    setup.selection = {.rule = MapSelection::Rule::face_axis, .centre = in.light.position};
    record(trace, [&](Trace& t) {
        t.set_frame(Space::light, glm::translate(glm::dmat4(1.0), -in.light.position));  // world axes about the light
        record_range(t, in.light, range, !in.light.range);
        record_faces(t, setup);
    });
    record_output(setup, in.caster_points(), trace);
    return setup;
}

std::vector<SettingSpec> cube_settings() { return {body_kernel_setting()}; }

}  // namespace shadowlab
