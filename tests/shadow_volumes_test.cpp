// Stencil shadow volumes: the silhouette, the extrusion to infinity, z-pass against z-fail, and
// agreement with the exact reference.
#include <gtest/gtest.h>

#include <map>
#include <memory>

#include "geometry/homogeneous_plane.hpp"
#include "metrics/measurement.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"
#include "volumes/stencil_count.hpp"
#include "volumes/volumes_technique.hpp"

using namespace shadowlab;
using shadowlab::testing::source_path;

namespace {

Scene scene_file(const std::string& name) { return load_scene(source_path("data/scenes/" + name + ".json")); }

Settings count_rule(const std::string& rule) {
    return resolve_settings("volumes", {volumes_count_setting()}, {{"count", rule}});
}

Measurement measure_volumes(const MeasureContext& context, const std::string& rule) {
    return measure(context, *find_method("volumes"), count_rule(rule), 0, 0.0);
}

ShadowVolume volume_of(const Scene& scene, const WorldTriangles& triangles) {
    return extrude_volume(find_silhouette(caster_topology(scene, triangles), triangles, scene.light), scene.light);
}

// A floating sphere over a ground that does not cast.
Scene sphere_scene() {
    Scene scene;
    SceneObject ground;
    ground.name = "ground";
    ground.shape = Shape::plane;
    ground.size = {40, 1, 40};
    ground.casts = false;
    SceneObject ball;
    ball.name = "ball";
    ball.shape = Shape::sphere;
    ball.radius = 1.5;
    ball.position = {0, 3, 0};
    scene.objects = {ground, ball};
    scene.light.direction = glm::normalize(glm::dvec3(0.3, -1, 0.2));
    scene.camera.position = {0, 8, 14};
    scene.camera.target = {0, 0, 0};
    return scene;
}

}  // namespace

TEST(ShadowVolumes, PlaneThroughFinitePointsIsTheTrianglesPlane) {
    const glm::dvec3 a(1, 2, 3), b(4, 2, 3), c(1, 5, 4);
    const glm::dvec4 plane = plane_through(glm::dvec4(a, 1), glm::dvec4(b, 1), glm::dvec4(c, 1));
    const glm::dvec3 n = glm::cross(b - a, c - a);
    for (const glm::dvec3 x : {glm::dvec3(0, 0, 0), glm::dvec3(7, -1, 2), glm::dvec3(-3, 4, 9)})
        EXPECT_NEAR(glm::dot(plane, glm::dvec4(x, 1)), glm::dot(n, x - a), 1e-9);
}

TEST(ShadowVolumes, SilhouetteOfAClosedConvexMeshIsOneClosedLoop) {
    const Scene scene = sphere_scene();
    const WorldTriangles triangles = tessellate(scene);
    const std::vector<ObjectTopology> topology = caster_topology(scene, triangles);
    ASSERT_EQ(topology.size(), 1u);
    EXPECT_TRUE(topology[0].closed());
    const Silhouette s = find_silhouette(topology, triangles, scene.light);
    ASSERT_GE(s.edges.size(), 12u);
    // Each silhouette vertex starts exactly one edge and ends exactly one; walking from any edge
    // visits every edge before it comes back.
    using Key = std::tuple<double, double, double>;
    auto key = [](const glm::dvec3& p) { return Key{p.x, p.y, p.z}; };
    std::map<Key, const SilhouetteEdge*> starting;
    std::map<Key, int> ending;
    for (const SilhouetteEdge& e : s.edges) {
        EXPECT_EQ(e.multiplicity, 1);
        EXPECT_TRUE(starting.emplace(key(e.a), &e).second) << "two edges leave one vertex";
        ++ending[key(e.b)];
    }
    for (const auto& [vertex, count] : ending) EXPECT_EQ(count, 1);
    const SilhouetteEdge* edge = &s.edges[0];
    size_t walked = 0;
    do {
        ASSERT_TRUE(starting.count(key(edge->b))) << "the loop is open";
        edge = starting.at(key(edge->b));
        ++walked;
    } while (edge != &s.edges[0] && walked <= s.edges.size());
    EXPECT_EQ(walked, s.edges.size());
}

TEST(ShadowVolumes, QuadsReachInfinityAndOnlyAPointLightHasABackCap) {
    Scene scene = sphere_scene();
    const WorldTriangles triangles = tessellate(scene);
    const ShadowVolume directional = volume_of(scene, triangles);
    EXPECT_TRUE(directional.back_cap.empty());
    for (const VolumePolygon& q : directional.quads) {
        ASSERT_EQ(q.vertices.size(), 4u);
        EXPECT_EQ(q.vertices[0].w, 1.0);
        EXPECT_EQ(q.vertices[1].w, 1.0);
        EXPECT_EQ(q.vertices[2], glm::dvec4(scene.light.direction, 0.0));  // every point goes to the light's direction
    }
    scene.light.type = LightType::point;
    scene.light.position = {2, 10, 1};
    const ShadowVolume point = volume_of(scene, triangles);
    const Silhouette s = find_silhouette(caster_topology(scene, triangles), triangles, scene.light);
    EXPECT_EQ(point.back_cap.size(), s.back_cap.size());
    EXPECT_EQ(point.front_cap.size() + point.back_cap.size(), triangles.triangles.size() - 2);  // all but the ground
    for (const VolumePolygon& q : point.quads)
        EXPECT_NEAR(glm::dot(glm::normalize(glm::dvec3(q.vertices[2])),
                             glm::normalize(glm::dvec3(q.vertices[1]) - scene.light.position)), 1.0, 1e-12);
}

TEST(ShadowVolumes, ZPassAndZFailAgreeWhenTheEyeIsOutsideEveryVolume) {
    const Scene scene = scene_file("volumes");
    const WorldTriangles triangles = tessellate(scene);
    const ReferenceImage image = exact_reference(scene, triangles, 320, 180);
    const StencilCounts c = count_stencil(volume_of(scene, triangles), scene.camera, image, CountRule::zfail);
    size_t visible = 0, shadowed = 0;
    for (size_t i = 0; i < c.zpass.size(); ++i) {
        if (!image.visible[i]) continue;
        ++visible;
        shadowed += c.zfail[i] != 0;
        EXPECT_EQ(c.zpass[i], c.zfail[i]) << "pixel " << i;
    }
    EXPECT_GT(shadowed, visible / 20) << "the scene has shadows to count";
}

TEST(ShadowVolumes, WithTheEyeInsideAVolumeZPassIsWrongAndZFailRight) {
    const MeasureContext context = prepare_measurement(scene_file("volumes_eye_in_shadow"), 320, 180);
    const Measurement zpass = measure_volumes(context, "zpass"), zfail = measure_volumes(context, "zfail");
    EXPECT_GT(zpass.error.misclassified, 0.3);
    EXPECT_LT(zfail.error.misclassified, 1e-3);
    ASSERT_FALSE(zpass.limits.empty());
    EXPECT_TRUE(shadowlab::testing::has_note(zpass.limits, NoteKind::eye_in_volume)) << describe(zpass.limits);
    EXPECT_TRUE(zfail.limits.empty()) << describe(zfail.limits);
}

TEST(ShadowVolumes, ZFailMatchesTheExactReferenceOnClosedMeshes) {
    for (const char* name : {"volumes", "box_on_plane", "light_overhead"}) {
        const MeasureContext context = prepare_measurement(scene_file(name), 640, 360);
        const Measurement m = measure_volumes(context, "zfail");
        EXPECT_GT(m.error.receiver_pixels, 640u * 360u / 4) << name;
        EXPECT_LE(m.error.misclassified, 1e-3) << name;
        EXPECT_TRUE(m.limits.empty()) << name << ": " << describe(m.limits);
        ASSERT_TRUE(m.geometry);
        EXPECT_GT(m.geometry->polygons, 0u);
        EXPECT_GE(m.geometry->fill_max, m.geometry->fill_mean);
        EXPECT_GT(m.geometry->fill_mean, 0.0);
    }
}

TEST(ShadowVolumes, OpenAndNonManifoldMeshesAreNamedAndStillShadowRight) {
    Scene scene = sphere_scene();
    scene.objects.pop_back();
    SceneObject sheet;  // a plane is open: four boundary edges
    sheet.name = "sheet";
    sheet.shape = Shape::plane;
    sheet.size = {3, 1, 3};
    sheet.position = {-3, 2.5, 0};
    sheet.rotation_deg = {20, 0, 10};
    SceneObject fan;  // three triangles on one edge
    fan.name = "fan";
    fan.shape = Shape::mesh;
    fan.position = {3, 2, 0};
    fan.mesh = std::make_shared<TriangleMesh>(
        TriangleMesh{{{0, 0, -1}, {0, 0, 1}, {1.5, 0.2, 0}, {-1, 0.8, 0}, {0.2, 1.5, 0.1}}, {{0, 1, 2}, {0, 1, 3}, {1, 0, 4}}});
    scene.objects.push_back(sheet);
    scene.objects.push_back(fan);

    const WorldTriangles triangles = tessellate(scene);
    const std::vector<ObjectTopology> topology = caster_topology(scene, triangles);
    ASSERT_EQ(topology.size(), 2u);
    EXPECT_EQ(topology[0].name, "sheet");
    EXPECT_EQ(topology[0].open_edges, 4);
    EXPECT_EQ(topology[1].name, "fan");
    EXPECT_EQ(topology[1].non_manifold_edges, 1);

    const MeasureContext context = prepare_measurement(scene, 320, 180);
    const Measurement m = measure_volumes(context, "zfail");
    ASSERT_FALSE(m.limits.empty());
    EXPECT_TRUE(shadowlab::testing::has_note(m.limits, NoteKind::open_mesh)) << describe(m.limits);
    EXPECT_NE(describe(m.limits).find("'sheet' (4 open, 0 non-manifold edges)"), std::string::npos) << describe(m.limits);
    EXPECT_NE(describe(m.limits).find("'fan'"), std::string::npos) << describe(m.limits);
    EXPECT_LE(m.error.misclassified, 2e-3) << "two-sided volumes shadow the ground right";
    size_t ground_in_shadow = 0;
    for (size_t i = 0; i < context.reference.lit.size(); ++i)
        ground_in_shadow += context.reference.visible[i] && context.reference.object[i] == 0 && !context.reference.lit[i];
    EXPECT_GT(ground_in_shadow, 200u) << "both casters shadow the ground";
}

TEST(ShadowVolumes, TraceListsTheStepsWithTheirGeometryAndChangesNothing) {
    const Scene scene = scene_file("volumes");
    const WorldTriangles triangles = tessellate(scene);
    const ReferenceImage image = exact_reference(scene, triangles, 160, 90);
    const Method& volumes = *find_method("volumes");
    const Settings settings = count_rule("zfail");
    Trace trace;
    const GeometryResult traced = volumes.compute_geometry(scene, triangles, image, settings, &trace);
    const GeometryResult plain = volumes.compute_geometry(scene, triangles, image, settings, nullptr);
    EXPECT_EQ(traced.shadowed, plain.shadowed);
    for (const char* id : {"volumes.topology", "volumes.light-facing", "volumes.silhouette", "volumes.extrusion",
                           "volumes.caps", "volumes.projection", "volumes.count"})
        EXPECT_NE(trace.find(id), nullptr) << id;
    const auto& silhouette = std::get<SegmentSet>(trace.find("volumes.silhouette")->geometry.at(0).geometry);
    EXPECT_GT(silhouette.segments.size(), 20u);
    const auto& quads = std::get<PolygonSet>(trace.find("volumes.extrusion")->geometry.at(0).geometry);
    EXPECT_EQ(quads.polygons.size(), silhouette.segments.size());
    size_t at_infinity = 0;
    for (const glm::dvec4& v : quads.vertices) at_infinity += v.w == 0.0;
    EXPECT_EQ(at_infinity, 2 * quads.polygons.size());
}

TEST(ShadowVolumes, BadCountRuleIsRejected) {
    EXPECT_THROW(count_rule("zmaybe"), std::invalid_argument);
}
