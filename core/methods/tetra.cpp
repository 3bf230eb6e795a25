// Tetrahedron shadow maps (Liao 2010; bgfx example 16). The regular tetrahedron about the light has
// four faces; the direction a_f to face f's centre is its axis, the four axes unit, pairwise at
// a_f . a_g = -1/3, summing to zero. Its vertices lie along -a_f (the vertex opposite face f), so
// face f's corners are the directions -a_g, g != f, at a_f . (-a_g) = 1/3: 70.5° off its axis, the
// face's field of view. A direction r meets face f's plane r . a_f = h at h / (r . a_f): the face of
// r is the one of largest r . a_f, so the four faces cover the sphere of directions once, meeting at
// the planes r . (a_f - a_g) = 0 through the light.
//
// The central projection of a face's spherical triangle onto its plane is the face's equilateral
// triangle, a perspective map along a_f. The texture is the square cut by its two diagonals into four
// triangles, each with its base on an edge of the square and its apex at the centre; an affine map
// of (u, v) takes each face's triangle onto its quarter, so each face stays one linear 4x4 (the
// affine map times the face's perspective) over the whole texture, drawn only inside its quarter (its
// mask; Liao uses a stencil). Three faces meet at one vertex of the tetrahedron: with that vertex at
// the centre they unfold edge to edge (bottom, right, top), so two diagonals' halves join one face's
// image to the next; the fourth face (left) meets its neighbours at the square's centre only.
//
// A lookup near a diagonal reads the nearest texel, or a filter's taps, across it: the neighbour's
// depth, from another direction across the fourth face's edges. As bgfx widens its faces' fields of
// view, each face's triangle is enlarged about its centre by s so that `margin` texels of its own
// quarter lie beyond its edges: the face draws its casters there too, and the reads near its edges
// stay its own.
#include "methods/tetra.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <glm/gtc/matrix_transform.hpp>

#include "maps/map_mask.hpp"
#include "math/invariant.hpp"
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
    std::array<glm::dvec2, 3> quarter;   // its triangle of the texture, counter-clockwise, apex at the centre last
    std::array<int, 3> corner_opposite;  // at each corner of the quarter: the vertex opposite that face (-a_g)
};

const double kLow = -std::sqrt(1.0 / 3.0), kAcross = std::sqrt(2.0 / 3.0);  // a face's axis below or above level
const glm::dvec2 kCentre{0.5, 0.5};
// The faces in the order of the maps: the quarters bottom, right, top around the vertex opposite
// face 3 (at the centre), and face 3 on the left, its corners turned as its neighbours' are.
const std::array<Face, 4> kFaces{{
    {"-z low", {0.0, kLow, -kAcross}, {{{0, 0}, {1, 0}, kCentre}}, {1, 2, 3}},
    {"-x high", {-kAcross, -kLow, 0.0}, {{{1, 0}, {1, 1}, kCentre}}, {2, 0, 3}},
    {"+x high", {kAcross, -kLow, 0.0}, {{{1, 1}, {0, 1}, kCentre}}, {0, 1, 3}},
    {"+z low", {0.0, kLow, kAcross}, {{{0, 1}, {0, 0}, kCentre}}, {2, 1, 0}},
}};

// The affine map of the plane taking triangle `from` onto `to`, acting on homogeneous (u, v, 1).
glm::dmat3 affine_between(const std::array<glm::dvec2, 3>& from, const std::array<glm::dvec2, 3>& to) {
    const auto columns = [](const std::array<glm::dvec2, 3>& t) {
        return glm::dmat3(glm::dvec3(t[0], 1.0), glm::dvec3(t[1], 1.0), glm::dvec3(t[2], 1.0));
    };
    return columns(to) * glm::inverse(columns(from));
}

// The affine map of (u, v) as a 4x4 on (u w, v w, d_pre, w): u and v's rows from it, depth and w kept.
glm::dmat4 lifted(const glm::dmat3& affine) {
    glm::dmat4 m(1.0);
    for (int row = 0; row < 2; ++row) {
        m[0][row] = affine[0][row];
        m[1][row] = affine[1][row];
        m[3][row] = affine[2][row];
    }
    return m;
}

// Face f's corners: the directions from the light to the tetrahedron's vertices it holds.
std::array<glm::dvec3, 3> corner_directions(const Face& face) {
    return {-kFaces[face.corner_opposite[0]].axis, -kFaces[face.corner_opposite[1]].axis,
            -kFaces[face.corner_opposite[2]].axis};
}

// The enlargement s of each face's triangle about its centre that leaves `margin` texels of its
// quarter beyond its edges: a quarter's centroid lies a sixth of the texture's side from its base
// (its nearest edge), so its image shrunk by 1 / s leaves (1 - 1 / s) R / 6 texels there. At most 2
// (a margin of R / 12), named when it cuts the margin.
double enlargement(double margin, int resolution, ShadowSetup& setup) {
    const double most = resolution / 12.0;
    if (margin > most)
        add_fallback(setup, Note{NoteKind::margin_reduced, "margin " + label_number(margin) + " texels cut to " +
                                                               label_number(most) + " in a texture of " +
                                                               std::to_string(resolution) + " texels a side"});
    return 1.0 / (1.0 - 6.0 * std::min(margin, most) / resolution);
}

ShadowMap face_map(const Light& light, const LightRange& range, int f, double s) {
    const Face& face = kFaces[f];
    const glm::dmat4 light_from_world =
        light_basis(face.axis, stable_up_hint(face.axis), light.position).light_from_world;
    // A face's corner lies 2√2 from its axis in tangents, the enlarged face's 2√2 s: a point at
    // distance r lies at least r / √(1 + 8 s²) along its face's axis (r / 3 unenlarged), the near
    // plane's share that keeps every point of the range.
    const double face_near = range.near / std::sqrt(1.0 + 8.0 * s * s);
    const ShadowMap perspective =
        perspective_map_of(light_from_world, Aabb{{-1.0, -1.0, face_near}, {1.0, 1.0, range.far}});
    std::array<glm::dvec2, 3> seen;  // the face's triangle under its perspective, enlarged by s about its centre
    const std::array<glm::dvec3, 3> corners = corner_directions(face);
    const glm::dvec2 centre(world_to_uvz(perspective, light.position + face.axis));
    for (int k = 0; k < 3; ++k)
        seen[k] = centre + s * (glm::dvec2(world_to_uvz(perspective, light.position + corners[k])) - centre);
    const glm::dmat3 onto_quarter = affine_between(seen, face.quarter);
    assert_invariant(glm::determinant(onto_quarter) > 0.0);  // the unfolding keeps every face's turn
    ShadowMap map = perspective;
    map.world_to_uvz = lifted(onto_quarter) * perspective.world_to_uvz;
    map.face_axis = face.axis;
    for (int k = 0; k < 3; ++k) map.mask.push_back(left_of(face.quarter[k], face.quarter[(k + 1) % 3]));
    return map;
}

// ---- steps ----

void record_axes(Trace& t, const Light& light, double length) {
    Step& step = t.add("tetra-axes", "The tetrahedron's faces",
                       "four face axes a_f, unit, a_f . a_g = -1/3, summing to 0; face f's corners along -a_g "
                       "(70.5° off its axis); a point belongs to the face of largest (p - light) . a_f",
                       Space::world);
    draw_light(step, light, light.position, 0.0);
    std::vector<std::pair<glm::dvec3, glm::dvec3>> edges;
    for (int f = 0; f < 4; ++f) {
        draw_arrow(step, std::string("a") + std::to_string(f) + " " + kFaces[f].name, light.position, kFaces[f].axis,
                   length, Role::step);
        step.value(std::string("a") + std::to_string(f), kFaces[f].axis);
        for (int g = f + 1; g < 4; ++g)
            edges.push_back(
                {light.position - 3.0 * length * kFaces[f].axis, light.position - 3.0 * length * kFaces[g].axis});
    }
    step.shape("tetrahedron", SegmentSet{edges}, Role::map);
}

// Face f's cone of directions as the pyramid from the light to the tetrahedron's face f at `length`
// along its axis (the tetrahedron of step tetra-axes): the part of the world the face's map serves.
PolygonSet face_pyramid(const Light& light, const Face& face, double length) {
    std::vector<glm::dvec4> base;
    for (const glm::dvec3& corner : corner_directions(face))
        base.emplace_back(light.position + length * corner / glm::dot(corner, face.axis), 1.0);
    const glm::dvec4 apex(light.position, 1.0);
    PolygonSet pyramid;
    pyramid.add(base);
    for (int k = 0; k < 3; ++k) pyramid.add({apex, base[(k + 1) % 3], base[k]});
    return pyramid;
}

// Each face's cone, its name beyond the tip of its axis's arrow (`length` from the light).
void record_faces(Trace& t, const ShadowSetup& setup, const Light& light, double length) {
    for (int f = 0; f < 4; ++f) {
        const ShadowMap& map = setup.maps[f];
        const std::string name = std::string("face ") + kFaces[f].name;
        t.add("tetra-face-" + std::to_string(f), "Face " + std::string(kFaces[f].name),
              "a perspective map along a" + std::to_string(f) +
                  " whose triangle (tangents up to 2√2 from the axis) an affine map of (u, v) takes onto its quarter "
                  "of the texture",
              Space::world)
            .value("world_to_uvz", map.world_to_uvz)
            .map_shape(f, name, face_pyramid(light, kFaces[f], length), Role::map)
            .map_shape(f, name + " label", Label{light.position + 1.5 * length * kFaces[f].axis, name});
    }
}

void record_packing(Trace& t) {
    Step& packing = t.add("tetra-packing", "The packing",
                          "the square cut by its diagonals: each face's triangle with its base on an edge and its "
                          "apex at the centre, drawn only there (its mask); the faces around one vertex unfold "
                          "edge to edge",
                          Space::unit);
    for (int f = 0; f < 4; ++f) {
        const Face& face = kFaces[f];
        const auto corner = [&](int k, double depth) { return glm::dvec4(face.quarter[k], depth, 1.0); };
        PolygonSet prism;
        prism.add({corner(0, 0.0), corner(2, 0.0), corner(1, 0.0)})
            .add({corner(0, 1.0), corner(1, 1.0), corner(2, 1.0)});
        const glm::dvec2 middle = (face.quarter[0] + face.quarter[1] + face.quarter[2]) / 3.0;
        packing.map_shape(f, std::string("quarter ") + face.name, prism)
            .map_shape(f, std::string("quarter label ") + face.name, Label{{middle, 1.0}, face.name});
    }
}

}  // namespace

std::array<glm::dvec3, 4> tetra_face_axes() { return {kFaces[0].axis, kFaces[1].axis, kFaces[2].axis, kFaces[3].axis}; }

ShadowSetup compute_tetra(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    if (!omni_or_focused("tetra", in, s, setup, trace)) return setup;
    const LightRange range = omni_range(in);
    const double enlarged = enlargement(s.number("margin"), in.texture_resolution, setup);
    for (int f = 0; f < 4; ++f) setup.maps.push_back(face_map(in.light, range, f, enlarged));
    setup.selection = {.rule = MapSelection::Rule::face_axis, .centre = in.light.position};
    record(trace, [&](Trace& t) {
        t.set_frame(Space::light, glm::translate(glm::dmat4(1.0), -in.light.position));  // world axes about the light
        record_range(t, in.light, range, !in.light.range);
        const double axis_length = 0.5 * range.near + 0.1 * range.far;
        record_axes(t, in.light, axis_length);
        record_faces(t, setup, in.light, axis_length);
        record_packing(t);
    });
    record_output(setup, in.caster_points(), trace);
    return setup;
}

std::vector<SettingSpec> tetra_settings() {
    return {body_kernel_setting(),
            {.name = "margin",
             .description = "texels of each face's quarter of the texture beyond its triangle's edges, where it draws "
                            "on so that lookups and filter taps near an edge read its own depths",
             .default_value = "2",
             .min = 0.0,
             .max = 64.0}};
}

}  // namespace shadowlab
