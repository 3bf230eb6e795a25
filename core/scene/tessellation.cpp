#include "scene/tessellation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shadowlab {
namespace {

// Two triangles of the quad a, b, c, d (counter-clockwise).
void add_quad(TriangleMesh& mesh, int a, int b, int c, int d) {
    mesh.triangles.push_back({a, b, c});
    mesh.triangles.push_back({a, c, d});
}

TriangleMesh box(const glm::dvec3& size) {
    const auto corners = Aabb{-size / 2.0, size / 2.0}.corners();
    TriangleMesh mesh{{corners.begin(), corners.end()}, {}};
    // Corner i takes x, y, z from max by bits 0, 1, 2; the faces -x, +x, -y, +y, -z, +z.
    static constexpr int faces[6][4] = {{0, 4, 6, 2}, {5, 1, 3, 7}, {0, 1, 5, 4},
                                        {6, 7, 3, 2}, {1, 0, 2, 3}, {4, 5, 7, 6}};
    for (const auto& f : faces) add_quad(mesh, f[0], f[1], f[2], f[3]);
    return mesh;
}

TriangleMesh plane(const glm::dvec3& size) {
    const double x = size.x / 2.0, z = size.z / 2.0;
    TriangleMesh mesh{{{-x, 0.0, -z}, {-x, 0.0, z}, {x, 0.0, z}, {x, 0.0, -z}}, {}};
    add_quad(mesh, 0, 1, 2, 3);
    return mesh;
}

// A ring of `count` vertices around the y axis; a single vertex (pole, cap centre) has count 1.
struct Ring {
    int first, count;
    int at(int j) const { return first + j % count; }
};

// The angle grows counter-clockwise seen from +y.
Ring add_ring(TriangleMesh& mesh, double radius, double y, int slices) {
    const Ring ring{static_cast<int>(mesh.vertices.size()), radius > 0.0 ? slices : 1};
    for (int j = 0; j < ring.count; ++j) {
        const double angle = 2.0 * std::numbers::pi * j / slices;
        mesh.vertices.push_back({radius * std::cos(angle), y, -radius * std::sin(angle)});
    }
    return ring;
}

// The surface of revolution of a profile of (radius, y) points listed from bottom to top, radius 0
// at a pole or a cap's centre. Each band is wound to face the side it sweeps toward as the angle
// grows with y going up: away from the axis on a side, down on a bottom cap, up on a top cap.
TriangleMesh revolve(const std::vector<glm::dvec2>& profile, int slices) {
    TriangleMesh mesh;
    Ring lower = add_ring(mesh, profile[0].x, profile[0].y, slices);
    for (std::size_t i = 1; i < profile.size(); ++i) {
        const Ring upper = add_ring(mesh, profile[i].x, profile[i].y, slices);
        for (int j = 0; j < slices; ++j) {
            const int b0 = lower.at(j), b1 = lower.at(j + 1), t0 = upper.at(j), t1 = upper.at(j + 1);
            if (lower.count > 1) mesh.triangles.push_back({b0, b1, t1});
            if (upper.count > 1) mesh.triangles.push_back({b0, t1, t0});
        }
        lower = upper;
    }
    return mesh;
}

TriangleMesh sphere(double radius, int slices, int stacks) {
    std::vector<glm::dvec2> profile;
    for (int i = 0; i <= stacks; ++i) {
        const double polar = std::numbers::pi * i / stacks;  // from the south pole up
        const bool pole = i == 0 || i == stacks;             // sin(pi) is not exactly 0
        profile.push_back({pole ? 0.0 : radius * std::sin(polar), -radius * std::cos(polar)});
    }
    return revolve(profile, slices);
}

TriangleMesh cylinder(double radius, double height, int slices) {
    const double h = height / 2.0;
    return revolve({{0.0, -h}, {radius, -h}, {radius, h}, {0.0, h}}, slices);
}

// A primitive's triangles in its local space (not for meshes, which carry their own).
TriangleMesh primitive(const SceneObject& object, int segments) {
    const int slices = std::max(3, segments), stacks = std::max(2, segments / 2);
    switch (object.shape) {
        case Shape::box: return box(object.size);
        case Shape::plane: return plane(object.size);
        case Shape::sphere: return sphere(object.radius, slices, stacks);
        case Shape::cylinder: return cylinder(object.radius, object.height, slices);
        case Shape::mesh: break;
    }
    return {};
}

// The alpha test of a mesh's triangle t, null for an opaque one.
TriangleAlpha alpha_of(const SceneObject& object, std::size_t t) {
    if (!object.mesh || object.mesh->surfaces.empty()) return {};
    const TriangleSurface& surface = object.mesh->surfaces[t];
    const bool tested = surface.material >= 0 && surface.material < int(object.material_alpha.size());
    return tested ? TriangleAlpha{.test = object.material_alpha[surface.material], .uv = surface.uv} : TriangleAlpha{};
}

// The base colour of a mesh's triangle t, null for none; its texture coordinates where the file gave them.
TriangleColour colour_of(const SceneObject& object, std::size_t t) {
    if (!object.mesh || object.mesh->surfaces.empty()) return {};
    const TriangleSurface& surface = object.mesh->surfaces[t];
    const bool coloured = surface.material >= 0 && surface.material < int(object.material_colour.size());
    return coloured ? TriangleColour{.colour = object.material_colour[surface.material], .uv = surface.uv}
                    : TriangleColour{};
}

bool has_colour(const SceneObject& object) {
    return std::any_of(object.material_colour.begin(), object.material_colour.end(),
                       [](const std::shared_ptr<const BaseColour>& colour) { return colour != nullptr; });
}

bool has_alpha_test(const SceneObject& object) {
    return std::any_of(object.material_alpha.begin(), object.material_alpha.end(),
                       [](const std::shared_ptr<const AlphaTest>& test) { return test != nullptr; });
}

void append(WorldTriangles& out, const TriangleMesh& mesh, const glm::dmat4& model, int object) {
    const int base = static_cast<int>(out.vertices.size());
    for (const glm::dvec3& v : mesh.vertices) out.vertices.push_back(glm::dvec3(model * glm::dvec4(v, 1.0)));
    for (const std::array<int, 3>& t : mesh.triangles) {
        out.triangles.push_back({base + t[0], base + t[1], base + t[2]});
        out.object.push_back(object);
    }
}

}  // namespace

WorldTriangles tessellate(const Scene& scene, int segments) {
    WorldTriangles out;
    const bool alpha_tested = std::any_of(scene.objects.begin(), scene.objects.end(), has_alpha_test);
    const bool coloured = std::any_of(scene.objects.begin(), scene.objects.end(), has_colour);
    for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i) {
        const SceneObject& object = scene.objects[i];
        const std::size_t first = out.triangles.size();
        if (object.shape != Shape::mesh)
            append(out, primitive(object, segments), object.model_matrix(), i);
        else if (object.mesh)
            append(out, *object.mesh, object.model_matrix(), i);
        if (alpha_tested)
            for (std::size_t t = 0; t < out.triangles.size() - first; ++t) out.alpha.push_back(alpha_of(object, t));
        if (coloured)
            for (std::size_t t = 0; t < out.triangles.size() - first; ++t) out.colour.push_back(colour_of(object, t));
    }
    return out;
}

std::vector<bool> caster_flags(const Scene& scene) {
    std::vector<bool> flags;
    for (const SceneObject& object : scene.objects) flags.push_back(object.casts);
    return flags;
}

WorldTriangles relative_to(WorldTriangles triangles, const glm::dvec3& origin) {
    for (glm::dvec3& v : triangles.vertices) v -= origin;
    return triangles;
}

}  // namespace shadowlab
