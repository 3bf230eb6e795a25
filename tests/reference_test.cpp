// The scene's triangles (tessellation) and the ray-traced reference shadows built on them.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <utility>
#include <gtest/gtest.h>

#include "reference/exact_shadows.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 320, kHeight = 180;

Scene scene_of(std::vector<SceneObject> objects) {
    Scene scene;
    scene.objects = std::move(objects);
    return scene;
}

SceneObject object_of(Shape shape, const glm::dvec3& position = glm::dvec3(0.0)) {
    SceneObject object;
    object.shape = shape;
    object.position = position;
    return object;
}

std::array<glm::dvec3, 3> corners(const WorldTriangles& mesh, std::size_t i) {
    const auto& t = mesh.triangles[i];
    return {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
}

// Twice the area, along the normal of a counter-clockwise triangle.
glm::dvec3 area_vector(const std::array<glm::dvec3, 3>& t) { return glm::cross(t[1] - t[0], t[2] - t[0]); }

double surface_area(const WorldTriangles& mesh) {
    double area = 0.0;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) area += glm::length(area_vector(corners(mesh, i))) / 2.0;
    return area;
}

// The divergence theorem: V = 1/6 sum a . (b x c), positive when the triangles face outward.
double signed_volume(const WorldTriangles& mesh) {
    double volume = 0.0;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto t = corners(mesh, i);
        volume += glm::dot(t[0], glm::cross(t[1], t[2])) / 6.0;
    }
    return volume;
}

// Closed and consistently wound: every directed edge once, and its reverse once.
void expect_closed(const WorldTriangles& mesh) {
    std::map<std::pair<int, int>, int> edges;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
    for (const auto& [edge, count] : edges) {
        EXPECT_EQ(count, 1) << edge.first << "-" << edge.second;
        EXPECT_EQ(edges.count({edge.second, edge.first}), 1u) << edge.first << "-" << edge.second;
    }
}

// For a convex object around `centre`: every triangle faces away from it.
void expect_outward(const WorldTriangles& mesh, const glm::dvec3& centre) {
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto t = corners(mesh, i);
        EXPECT_GT(glm::dot(area_vector(t), (t[0] + t[1] + t[2]) / 3.0 - centre), 0.0) << "triangle " << i;
    }
}

// A ground plane (object 0) and a box floating above it (object 1), seen from above at an angle.
Scene floating_box(const Light& light) {
    SceneObject ground = object_of(Shape::plane);
    ground.size = {20.0, 1.0, 20.0};
    SceneObject box = object_of(Shape::box, {0.5, 2.0, -0.3});  // y from 1.5 to 2.5
    box.size = {2.0, 1.0, 2.0};
    box.rotation_deg = {0.0, 30.0, 0.0};
    Scene scene = scene_of({ground, box});
    scene.camera.position = {0.0, 8.0, 9.0};
    scene.camera.target = {0.0, 0.0, 0.0};
    scene.light = light;
    return scene;
}

Light directional(const glm::dvec3& direction) {
    Light light;
    light.direction = glm::normalize(direction);
    return light;
}

Light point_light(const glm::dvec3& position) {
    Light light;
    light.type = LightType::point;
    light.position = position;
    return light;
}

ReferenceImage trace(const Scene& scene) { return exact_reference(scene, tessellate(scene), kWidth, kHeight); }

// A point in the object's local frame.
glm::dvec3 local(const SceneObject& object, const glm::dvec3& world) {
    return glm::dvec3(glm::inverse(object.model_matrix()) * glm::dvec4(world, 1.0));
}

// Does the vertical line through p cross the box's footprint? (The box turns about y only.)
bool in_footprint(const SceneObject& box, const glm::dvec3& p) {
    const glm::dvec3 q = local(box, {p.x, box.position.y, p.z});
    return std::abs(q.x) < box.size.x / 2 && std::abs(q.z) < box.size.z / 2;
}

// Visible ground pixels, each with `inside` (its point under the box), leaving out those with a
// neighbouring ground pixel on the other side: the pixels within a pixel of the footprint's edge.
std::vector<std::pair<std::size_t, bool>> ground_pixels(const ReferenceImage& image, const SceneObject& box) {
    const auto at = [&](int x, int y) { return static_cast<std::size_t>(y) * image.width + x; };
    const auto inside = [&](std::size_t i) { return in_footprint(box, image.position[i]); };
    std::vector<std::pair<std::size_t, bool>> out;
    for (int y = 1; y + 1 < image.height; ++y)
        for (int x = 1; x + 1 < image.width; ++x) {
            const std::size_t i = at(x, y);
            if (image.object[i] != 0) continue;
            bool near_edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const std::size_t n = at(x + dx, y + dy);
                    near_edge = near_edge || (image.object[n] == 0 && inside(n) != inside(i));
                }
            if (!near_edge) out.push_back({i, inside(i)});
        }
    return out;
}

int lit_count(const ReferenceImage& image, const std::vector<std::pair<std::size_t, bool>>& pixels) {
    int lit = 0;
    for (const auto& [i, inside] : pixels) lit += image.lit[i];
    return lit;
}

// Ground (object 0) is seen, and all of it sees the light.
void expect_ground_all_lit(const Scene& scene) {
    const ReferenceImage image = trace(scene);
    const auto ground = ground_pixels(image, scene.objects[1]);
    ASSERT_GT(ground.size(), 1000u);
    EXPECT_EQ(lit_count(image, ground), static_cast<int>(ground.size()));
}

}  // namespace

TEST(ReferenceTessellation, BoxVolumeByTheDivergenceTheoremIsTheProductOfItsSizes) {
    SceneObject box = object_of(Shape::box, {1.0, -2.0, 3.0});
    box.size = {2.0, 3.0, 0.5};
    box.rotation_deg = {10.0, 25.0, -40.0};
    box.scale = {1.5, 1.0, 2.0};
    const WorldTriangles mesh = tessellate(scene_of({box}));
    EXPECT_EQ(mesh.triangles.size(), 12u);
    EXPECT_NEAR(signed_volume(mesh), 2.0 * 3.0 * 0.5 * 1.5 * 2.0, 1e-12);
    expect_closed(mesh);
    expect_outward(mesh, box.position);
}

TEST(ReferenceTessellation, PlaneIsTwoTrianglesFacingUp) {
    SceneObject plane = object_of(Shape::plane, {0.0, 1.0, 0.0});
    plane.size = {4.0, 1.0, 6.0};
    const WorldTriangles mesh = tessellate(scene_of({plane}));
    ASSERT_EQ(mesh.triangles.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        const glm::dvec3 n = area_vector(corners(mesh, i));
        EXPECT_GT(n.y, 0.0);
        EXPECT_NEAR(n.x, 0.0, 1e-12);
        EXPECT_NEAR(n.z, 0.0, 1e-12);
    }
    EXPECT_NEAR(surface_area(mesh), 24.0, 1e-12);
}

TEST(ReferenceTessellation, SphereAreaIsWithinTwoPercentOfFourPiRSquared) {
    SceneObject sphere = object_of(Shape::sphere, {-3.0, 2.0, 1.0});
    sphere.radius = 1.7;
    const WorldTriangles mesh = tessellate(scene_of({sphere}), 24);
    const double exact = 4.0 * std::numbers::pi * 1.7 * 1.7;
    EXPECT_NEAR(surface_area(mesh) / exact, 1.0, 0.02);
    EXPECT_GT(signed_volume(mesh), 0.0);
    expect_closed(mesh);
    expect_outward(mesh, sphere.position);
}

TEST(ReferenceTessellation, CylinderIsClosedOutwardAndNearItsVolume) {
    SceneObject cylinder = object_of(Shape::cylinder, {2.0, 0.5, -1.0});
    cylinder.radius = 0.8;
    cylinder.height = 2.5;
    cylinder.rotation_deg = {90.0, 0.0, 0.0};
    const WorldTriangles mesh = tessellate(scene_of({cylinder}), 24);
    EXPECT_EQ(mesh.triangles.size(), 4u * 24u);  // two per side quad, one per cap sector
    EXPECT_NEAR(signed_volume(mesh) / (std::numbers::pi * 0.8 * 0.8 * 2.5), 1.0, 0.02);
    expect_closed(mesh);
    expect_outward(mesh, cylinder.position);
}

TEST(ReferenceTessellation, MeshGoesThroughItsModelMatrix) {
    auto tetrahedron = std::make_shared<TriangleMesh>();
    tetrahedron->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    tetrahedron->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    SceneObject mesh_object = object_of(Shape::mesh, {5.0, 0.0, 0.0});
    mesh_object.mesh = tetrahedron;
    mesh_object.scale = glm::dvec3(2.0);
    const WorldTriangles mesh = tessellate(scene_of({mesh_object}));
    EXPECT_EQ(mesh.triangles.size(), 4u);
    EXPECT_NEAR(signed_volume(mesh), 8.0 / 6.0, 1e-12);
    EXPECT_EQ(mesh.vertices[1], glm::dvec3(7.0, 0.0, 0.0));
}

TEST(ReferenceTessellation, EachTriangleNamesItsObject) {
    SceneObject ground = object_of(Shape::plane), box = object_of(Shape::box), ball = object_of(Shape::sphere);
    ground.casts = false;
    const Scene scene = scene_of({ground, box, ball});
    const WorldTriangles mesh = tessellate(scene, 8);
    ASSERT_EQ(mesh.object.size(), mesh.triangles.size());
    const std::vector<int> expected_counts{2, 12, 2 * 8 * 4 - 2 * 8};  // sphere: 8 slices, 4 stacks
    for (int object = 0; object < 3; ++object)
        EXPECT_EQ(std::count(mesh.object.begin(), mesh.object.end(), object), expected_counts[object]);
    EXPECT_TRUE(std::is_sorted(mesh.object.begin(), mesh.object.end()));
    EXPECT_EQ(caster_flags(scene), (std::vector<bool>{false, true, true}));
}

TEST(ReferenceImageLayout, VisiblePointsProjectBackToTheirPixelCentres) {
    const Scene scene = floating_box(directional({0.0, -1.0, 0.0}));
    const ReferenceImage image = trace(scene);
    ASSERT_EQ(image.position.size(), static_cast<std::size_t>(kWidth * kHeight));
    const glm::dmat4 view_projection = scene.camera.projection_matrix() * scene.camera.view_matrix();
    int visible = 0, missed = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
            EXPECT_EQ(image.object[i] >= 0, image.visible[i] == 1);
            EXPECT_TRUE(image.visible[i] || !image.lit[i]);
            if (!image.visible[i]) {
                ++missed;
                continue;
            }
            ++visible;
            const glm::dvec4 clip = view_projection * glm::dvec4(image.position[i], 1.0);
            const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
            EXPECT_NEAR((ndc.x + 1.0) / 2.0 * kWidth, x + 0.5, 1e-3);
            EXPECT_NEAR((1.0 - ndc.y) / 2.0 * kHeight, y + 0.5, 1e-3);  // row 0 at the top
        }
    EXPECT_GT(visible, 0);
    EXPECT_GT(missed, 0);  // the sky above the 20 x 20 ground
}

TEST(ReferenceOverheadLight, ShadowIsExactlyTheFloatingBoxFootprint) {
    const Scene scene = floating_box(directional({0.0, -1.0, 0.0}));
    const ReferenceImage image = trace(scene);
    int inside = 0, outside = 0;
    for (const auto& [i, under_box] : ground_pixels(image, scene.objects[1])) {
        (under_box ? inside : outside) += 1;
        EXPECT_EQ(image.lit[i], under_box ? 0 : 1)
            << "ground point " << image.position[i].x << ", " << image.position[i].z;
    }
    EXPECT_GT(inside, 200);  // seen under the box, which floats
    EXPECT_GT(outside, 1000);
}

TEST(ReferenceSelfShadowing, BoxFacesTurnedFromTheLightAreNotLit) {
    const Light light = directional({0.4, -1.0, 0.3});
    const Scene scene = floating_box(light);
    const SceneObject& box = scene.objects[1];
    const ReferenceImage image = trace(scene);
    int lit = 0, unlit = 0;
    for (std::size_t i = 0; i < image.object.size(); ++i) {
        if (image.object[i] != 1) continue;
        // The face: the local axis along which the point is at the box's surface; skip edges.
        const glm::dvec3 q = local(box, image.position[i]) / (box.size / 2.0);
        const glm::dvec3 a = glm::abs(q);
        const int axis = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
        if (a[(axis + 1) % 3] > 0.98 || a[(axis + 2) % 3] > 0.98) continue;
        glm::dvec3 normal(0.0);
        normal[axis] = q[axis] > 0 ? 1.0 : -1.0;
        normal = glm::dmat3(box.model_matrix()) * normal;  // a rotation: the box is not scaled
        const bool faces_light = glm::dot(normal, light.direction) < 0.0;
        (faces_light ? lit : unlit) += 1;
        EXPECT_EQ(image.lit[i], faces_light ? 1 : 0) << "box point at local " << q.x << ", " << q.y << ", " << q.z;
    }
    EXPECT_GT(lit, 100);
    EXPECT_GT(unlit, 100);
}

TEST(ReferenceSelfShadowing, ShadowRaysLeaveFromTheSideOfTheSurfaceFacingTheLight) {
    // A light travelling up: the ground's top, which the camera sees, faces away from it. The ray
    // leaves from just below the ground and meets nothing: this is occlusion, as a shadow map
    // sees it (the ground at its own depth), not the N . L term of shading.
    expect_ground_all_lit(floating_box(directional({0.0, 1.0, 0.0})));
}

TEST(ReferencePointLight, OnlyCastersBetweenThePointAndTheLightShadowIt) {
    // Below the floating box, the light has nothing between it and the ground.
    expect_ground_all_lit(floating_box(point_light({0.5, 1.0, -0.3})));
    // Above it, the box shadows part of the ground.
    const Scene above = floating_box(point_light({0.5, 5.0, -0.3}));
    const ReferenceImage image = trace(above);
    const auto ground = ground_pixels(image, above.objects[1]);
    EXPECT_LT(lit_count(image, ground), static_cast<int>(ground.size()) - 200);
}

TEST(ReferenceCasting, ObjectsThatDoNotCastLeaveNoShadow) {
    Scene scene = floating_box(directional({0.0, -1.0, 0.0}));
    scene.objects[1].casts = false;
    expect_ground_all_lit(scene);
}

TEST(ReferenceShippedScene, BoxOnPlaneIsPartlyLit) {
    const Scene scene = load_scene(source_path("data/scenes/box_on_plane.json"));
    const ReferenceImage image = trace(scene);
    int visible = 0, lit = 0;
    for (std::size_t i = 0; i < image.visible.size(); ++i) {
        visible += image.visible[i];
        lit += image.lit[i];
    }
    ASSERT_GT(visible, 0);
    const double lit_fraction = static_cast<double>(lit) / visible;
    EXPECT_GT(lit_fraction, 0.0);
    EXPECT_LT(lit_fraction, 1.0);
}
