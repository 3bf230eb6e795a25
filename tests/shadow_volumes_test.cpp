// Stencil shadow volumes: the silhouette, the extrusion to infinity, z-pass against z-fail, the
// rasterized stencil count (shared edges counted once, unchanged when the scene moves far away), and
// agreement with the exact reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// The count a rule gives a scene at 640x360, and the ray-traced image it is judged against.
struct CountedScene {
    ReferenceImage image;
    StencilCounts counts;
};

CountedScene counted(const std::string& name) {
    Scene scene = scene_file(name);
    scene.camera.aspect = 640.0 / 360.0;
    const WorldTriangles triangles = tessellate(scene);
    ReferenceImage image = exact_reference(scene, triangles, 640, 360);
    StencilCounts counts = count_stencil(volume_of(scene, triangles), scene.camera, image, CountRule::zfail);
    return {std::move(image), std::move(counts)};
}

// Does a pixel next to visible pixel i (8-neighbourhood) see another object, nothing, or the other
// verdict: is i on a silhouette or a shadow's edge?
bool on_an_edge(const ReferenceImage& image, std::size_t i) {
    const int x = int(i % image.width), y = int(i / image.width);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= image.width || ny >= image.height) continue;
            const std::size_t j = std::size_t(ny) * image.width + nx;
            if (!image.visible[j] || image.object[j] != image.object[i] || image.lit[j] != image.lit[i]) return true;
        }
    return false;
}

// The visible pixels whose count (not 0: shadowed) disagrees with the ray-traced verdict.
std::vector<std::size_t> disagreeing(const std::vector<int>& count, const ReferenceImage& image) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < count.size(); ++i)
        if (image.visible[i] && (count[i] != 0) == bool(image.lit[i])) out.push_back(i);
    return out;
}

std::size_t visible_pixels(const ReferenceImage& image) {
    return std::size_t(std::count(image.visible.begin(), image.visible.end(), 1));
}

// x -> scale x + offset for every point of the volume (points at infinity keep their direction),
// the camera and the visible points.
void move(ShadowVolume& volume, Camera& camera, ReferenceImage& image, double scale, const glm::dvec3& offset) {
    for (std::vector<VolumePolygon>* list : {&volume.quads, &volume.front_cap, &volume.back_cap})
        for (VolumePolygon& p : *list)
            for (glm::dvec4& v : p.vertices) v = glm::dvec4(scale * glm::dvec3(v) + offset * v.w, v.w);
    camera.position = scale * camera.position + offset;
    camera.target = scale * camera.target + offset;
    camera.near *= scale;
    camera.far *= scale;
    for (glm::dvec3& p : image.position) p = scale * p + offset;
}

// At the origin looking down -z, 90 degrees square: pixel centre (x, y) of a 41x41 image sees the
// view direction ((x - 20) / 20.5, (20 - y) / 20.5, -1).
Camera square_camera() {
    Camera camera;
    camera.position = {0.0, 0.0, 0.0};
    camera.target = {0.0, 0.0, -1.0};
    camera.aspect = 1.0;
    camera.fov_y_deg = 90.0;
    return camera;
}

// A 41x41 image that sees nothing: only the fragments are counted.
ReferenceImage nothing_visible() {
    ReferenceImage image;
    image.width = image.height = 41;
    image.visible.assign(41 * 41, 0);
    image.position.assign(41 * 41, glm::dvec3(0.0));
    return image;
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
                             glm::normalize(glm::dvec3(q.vertices[1]) - scene.light.position)),
                    1.0, 1e-12);
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
    fan.mesh = std::make_shared<TriangleMesh>(TriangleMesh{
        {{0, 0, -1}, {0, 0, 1}, {1.5, 0.2, 0}, {-1, 0.8, 0}, {0.2, 1.5, 0.1}}, {{0, 1, 2}, {0, 1, 3}, {1, 0, 4}}});
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
    EXPECT_NE(describe(m.limits).find("'sheet' (4 open, 0 non-manifold edges)"), std::string::npos)
        << describe(m.limits);
    EXPECT_NE(describe(m.limits).find("'fan'"), std::string::npos) << describe(m.limits);
    EXPECT_LE(m.error.misclassified, 2e-3) << "two-sided volumes shadow the ground right";
    size_t ground_in_shadow = 0;
    for (size_t i = 0; i < context.reference.lit.size(); ++i)
        ground_in_shadow +=
            context.reference.visible[i] && context.reference.object[i] == 0 && !context.reference.lit[i];
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

TEST(ShadowVolumes, BadCountRuleIsRejected) { EXPECT_THROW(count_rule("zmaybe"), std::invalid_argument); }

// The rasterized count against the ray-traced shadows: the z-fail verdicts differ only on a small
// share of the visible pixels (measured: 12 of 147513 on the default scene, 0.008 %; 4 on volumes;
// none with the eye in a shadow), all on a silhouette or a shadow's edge, where the two sides of a
// pixel centre are a rounding apart (Embree traces in single precision).
TEST(ShadowVolumes, ZFailCountAgreesWithTheRayTracedShadowsButOnEdgePixels) {
    for (const char* name : {"volumes", "volumes_eye_in_shadow", "default"}) {
        const auto [image, counts] = counted(name);
        const std::vector<std::size_t> wrong = disagreeing(counts.zfail, image);
        EXPECT_LT(double(wrong.size()), 0.005 * visible_pixels(image)) << name;
        for (std::size_t i : wrong) EXPECT_TRUE(on_an_edge(image, i)) << name << ": pixel " << i << " inside a region";
    }
}

// With the eye inside a shadow volume the count from the eye starts off by one: z-pass is wrong on
// most of the image, z-fail (counting from infinity) right.
TEST(ShadowVolumes, ZPassCountIsWrongAndZFailRightWithTheEyeInAShadow) {
    const auto [image, counts] = counted("volumes_eye_in_shadow");
    const double visible = double(visible_pixels(image));
    EXPECT_GT(double(disagreeing(counts.zpass, image).size()), 0.3 * visible);
    EXPECT_LT(double(disagreeing(counts.zfail, image).size()), 0.005 * visible);
}

// The counts are computed relative to the eye: moving the whole scene 1e4 away and scaling it
// changes neither count nor the fragments at any but a few pixels.
TEST(ShadowVolumes, StencilCountsStayWhenTheSceneIsMovedFarAndScaled) {
    Scene scene = scene_file("volumes");
    scene.camera.aspect = 320.0 / 180.0;
    const WorldTriangles triangles = tessellate(scene);
    ReferenceImage image = exact_reference(scene, triangles, 320, 180);
    ShadowVolume volume = volume_of(scene, triangles);
    const StencilCounts before = count_stencil(volume, scene.camera, image, CountRule::zfail);
    move(volume, scene.camera, image, 3.0, glm::dvec3(1e4, -2e4, 1e4));
    const StencilCounts after = count_stencil(volume, scene.camera, image, CountRule::zfail);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < before.zfail.size(); ++i)
        changed += before.zpass[i] != after.zpass[i] || before.zfail[i] != after.zfail[i] ||
                   before.fragments[i] != after.fragments[i];
    EXPECT_LE(double(changed), 1e-3 * double(before.zfail.size()));
    EXPECT_GT(std::count(before.fragments.begin(), before.fragments.end(), 0), 0) << "the volume leaves pixels";
}

// Triangles fanned around a point that projects onto a pixel centre, their shared edges along the
// image's rows, columns and diagonals through pixel centres: with the top-left rule each covered
// centre is drawn exactly once (inclusive edges would draw some twice, exclusive ones none).
TEST(ShadowVolumes, TrianglesSharingEdgesDrawEachPixelCentreOnce) {
    const Camera camera = square_camera();
    const ReferenceImage image = nothing_visible();
    const std::size_t pixels = 41 * 41;
    ShadowVolume volume;
    const double reach = 12.0 / 20.5;  // twelve pixels from the centre
    std::vector<glm::dvec4> rim;
    for (int k = 0; k < 8; ++k) {
        const double a = k * std::atan(1.0);
        rim.emplace_back(reach * std::cos(a), reach * std::sin(a), -1.0, 1.0);
    }
    for (int k = 0; k < 8; ++k)
        volume.front_cap.push_back({{glm::dvec4(0.0, 0.0, -1.0, 1.0), rim[k], rim[(k + 1) % 8]}, 1, 0});
    const StencilCounts c = count_stencil(volume, camera, image, CountRule::zfail);
    std::size_t covered = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        EXPECT_LE(c.fragments[i], 1) << "pixel " << i % 41 << ", " << i / 41;
        covered += c.fragments[i] == 1;
    }
    const std::size_t centre = 20 * 41 + 20, along_row = 20 * 41 + 20 + 11, along_diagonal = (20 - 8) * 41 + 20 + 8;
    EXPECT_EQ(c.fragments[centre], 1);
    EXPECT_EQ(c.fragments[along_row], 1);
    EXPECT_EQ(c.fragments[along_diagonal], 1);
    // The octagon's area, 2 sqrt(2) r^2 with r = 12 pixels, to the pixels along its rim.
    EXPECT_NEAR(double(covered), 2.0 * std::sqrt(2.0) * 144.0, 24.0);
}

// A quad of the plane z = -2 - y, two corners behind the eye and two at infinity, covering the whole
// image: the ray through row y meets it at view depth 2 / (1 - dy), dy = (20 - y) / 20.5, and the
// near plane (1.2) clips it where that is less, the bottom rows, as a GPU clips it.
TEST(ShadowVolumes, TheNearPlaneClipsAFaceThatReachesBehindTheEye) {
    Camera camera = square_camera();
    camera.near = 1.2;
    ShadowVolume volume;
    volume.quads.push_back(
        {{{-10.0, -3.0, 1.0, 1.0}, {10.0, -3.0, 1.0, 1.0}, {10.0, 1.0, -1.0, 0.0}, {-10.0, 1.0, -1.0, 0.0}}});
    const StencilCounts c = count_stencil(volume, camera, nothing_visible(), CountRule::zpass);
    std::size_t clipped = 0;
    for (int y = 0; y < 41; ++y) {
        const bool beyond_near = 2.0 / (1.0 - (20 - y) / 20.5) >= camera.near;
        clipped += !beyond_near;
        for (int x = 0; x < 41; ++x) EXPECT_EQ(c.fragments[y * 41 + x], beyond_near ? 1 : 0) << x << ", " << y;
    }
    EXPECT_GT(clipped, 0u);
    EXPECT_LT(clipped, 41u);
}
