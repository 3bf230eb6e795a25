// Trapezoidal shadow maps: the trapezoid onto the unit square, the body inside the unit cube, depth
// along the light rays, the 80% rule and the named fallbacks.
#include <gtest/gtest.h>

#include "geometry/intersection_body.hpp"
#include "math/matrix.hpp"
#include "registry/method.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

ShadowSetup run_tsm(const ShadowInputs& in, const std::map<std::string, std::string>& set = {},
                    Trace* trace = nullptr) {
    const Method& tsm = *find_method("tsm");
    return tsm.compute_maps(in, resolve_settings("tsm", tsm.settings, set), trace);
}

// A street-level view over a town, lit from `light_direction`.
ShadowInputs town_view(const glm::dvec3& light_direction, const glm::dvec3& target = {10, 1, 100}) {
    Scene scene = random_town(200, 400.0, 7);
    scene.camera.position = {0, 3, 150};
    scene.camera.target = target;
    scene.camera.far = 300;
    scene.light.direction = glm::normalize(light_direction);
    return gather_inputs(scene);
}

// Views that warp: the town under four suns, and the shipped default scene.
std::vector<ShadowInputs> warped_views() {
    std::vector<ShadowInputs> views;
    for (const glm::dvec3& light :
         {glm::dvec3(-0.3, -1, -0.2), glm::dvec3(1, -0.3, 0.2), glm::dvec3(0.2, -0.5, 1), glm::dvec3(0.3, -0.4, -1)})
        views.push_back(town_view(light));
    views.push_back(gather_inputs(load_scene(source_path("data/scenes/default.json"))));
    return views;
}

template <class T>
T value_of(const Trace& trace, const std::string& step, const std::string& name) {
    if (const Step* s = trace.find(step))
        for (const NamedValue& v : s->values)
            if (v.name == name) return std::get<T>(v.value);
    ADD_FAILURE() << "no value " << name << " in step " << step;
    return T{};
}

std::vector<glm::dvec3> body_vertices(const ShadowInputs& in) {
    return intersection_body({in.frustum, in.scene_bounds, in.light.homogeneous()}, BodyKernel::float_clipper)
        .body.vertices;
}

}  // namespace

TEST(TsmTrapezoid, CornersMapToTheCornersOfTheUnitSquare) {
    const std::array<glm::dvec2, 4> square{glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)};
    for (const ShadowInputs& in : warped_views()) {
        Trace trace;
        const ShadowSetup setup = run_tsm(in, {}, &trace);
        ASSERT_TRUE(setup.fallbacks.empty()) << describe(setup.fallbacks);
        const glm::dmat4 n_t = value_of<glm::dmat4>(trace, "tsm-trapezoid-to-square", "N_T");
        for (int i = 0; i < 4; ++i) {
            const glm::dvec2 corner = value_of<glm::dvec2>(trace, "tsm-trapezoid", "corner" + std::to_string(i));
            const glm::dvec2 uv{transform_point(n_t, {corner, 0.0})};
            EXPECT_NEAR(uv.x, square[i].x, 1e-9) << "corner " << i;
            EXPECT_NEAR(uv.y, square[i].y, 1e-9) << "corner " << i;
        }
    }
}

TEST(TsmMap, EveryBodyVertexMapsIntoTheUnitCube) {
    for (const ShadowInputs& in : warped_views()) {
        const ShadowSetup setup = run_tsm(in);
        ASSERT_EQ(setup.maps.size(), 1u);
        ASSERT_TRUE(finite(setup.maps[0].world_to_uvz));
        for (const glm::dvec3& p : body_vertices(in)) {
            const glm::dvec3 uvz = world_to_uvz(setup.maps[0], p);
            EXPECT_TRUE(in_unit_cube(uvz, 1e-6)) << "(" << uvz.x << ", " << uvz.y << ", " << uvz.z << ")";
        }
    }
}

TEST(TsmMap, DepthGrowsStrictlyAlongEachLightRay) {
    for (const ShadowInputs& in : warped_views()) {
        const ShadowMap map = run_tsm(in).maps.at(0);
        const std::vector<glm::dvec3> body = body_vertices(in);
        glm::dvec3 centre{0.0};
        for (const glm::dvec3& p : body) centre += p / double(body.size());
        const double step = 1e-3 * in.scene_bounds.diagonal();
        for (const glm::dvec3& vertex : body)
            for (const glm::dvec3& p : {vertex, 0.5 * (vertex + centre)}) {
                const glm::dvec3 a = world_to_uvz(map, p), b = world_to_uvz(map, p + step * in.light.direction);
                EXPECT_GT(b.z, a.z);
                EXPECT_NEAR(a.x, b.x, 1e-9);
                EXPECT_NEAR(a.y, b.y, 1e-9);
            }
    }
}

TEST(TsmMap, BiasMovesThePointTowardTheLightByExactlyTheBias) {
    const ShadowInputs in = town_view({-0.3, -1, -0.2});
    const ShadowMap map = run_tsm(in).maps.at(0);
    const double bias = 0.25;
    for (const glm::dvec3& p : body_vertices(in)) {
        const glm::dvec4 h = map.world_to_uvz * glm::dvec4(p, 1.0);
        const double biased = (h.z - map.z_bias_scale * bias) / h.w;
        EXPECT_NEAR(biased, world_to_uvz(map, p - bias * in.light.direction).z, 1e-12);
    }
}

TEST(TsmFocus, TheFocusPointLandsOnTheEightyPercentLine) {
    for (const ShadowInputs& in : warped_views()) {
        Trace trace;
        run_tsm(in, {}, &trace);
        const glm::dmat4 n_t = value_of<glm::dmat4>(trace, "tsm-trapezoid-to-square", "N_T");
        const glm::dvec2 p_l = value_of<glm::dvec2>(trace, "tsm-focus-80", "p_L");
        EXPECT_NEAR(transform_point(n_t, {p_l, 0.0}).y, 0.8, 1e-9);
    }
}

TEST(TsmFocus, ALargerFocusMovesQAwayFromTheTopLine) {
    const ShadowInputs in = town_view({-0.3, -1, -0.2});
    double previous = 0.0;
    for (const char* focus : {"0.1", "0.3", "0.5", "0.7"}) {
        Trace trace;
        ASSERT_TRUE(run_tsm(in, {{"focus", focus}}, &trace).fallbacks.empty()) << "focus " << focus;
        const double eta = value_of<double>(trace, "tsm-focus-80", "eta");
        // q lies on l, η before the top line.
        const glm::dvec2 near_centre = value_of<glm::dvec2>(trace, "tsm-centre-line", "near_centre");
        const glm::dvec2 axis = value_of<glm::dvec2>(trace, "tsm-centre-line", "direction");
        const glm::dvec2 q = value_of<glm::dvec2>(trace, "tsm-focus-80", "q");
        const double top = value_of<double>(trace, "tsm-top-base-lines", "top");
        EXPECT_NEAR(glm::dot(q - near_centre, axis), top - eta, 1e-9 * eta);
        EXPECT_NEAR(glm::dot(q - near_centre, glm::dvec2(-axis.y, axis.x)), 0.0, 1e-9 * eta);
        EXPECT_GT(eta, previous) << "focus " << focus;
        previous = eta;
    }
}

TEST(TsmFallback, AViewParallelToTheLightHasADegenerateCentreLine) {
    const glm::dvec3 light{0.3, -0.6, -1};
    for (const glm::dvec3& view : {glm::normalize(light), -glm::normalize(light)}) {
        const ShadowInputs in = town_view(light, glm::dvec3(0, 3, 150) + view);
        const ShadowSetup setup = run_tsm(in);
        ASSERT_FALSE(setup.fallbacks.empty());
        EXPECT_TRUE(has_note(setup.fallbacks, NoteKind::degenerate_centre_line)) << describe(setup.fallbacks);
        EXPECT_TRUE(are_fallbacks(setup.fallbacks));
        ASSERT_TRUE(finite(setup.maps.at(0).world_to_uvz));
        for (const glm::dvec3& p : body_vertices(in)) EXPECT_TRUE(in_unit_cube(world_to_uvz(setup.maps[0], p), 1e-6));
    }
}

TEST(TsmFallback, AFocusRegionReachingPastTheEightyPercentLineAsksForNoWarp) {
    // Sun overhead, level view: the hull runs exactly from the near to the far centre, so a focus
    // region of the whole depth would have to land on the 80% line.
    const ShadowInputs in = town_view({0, -1, 0}, {0, 3, 100});
    const ShadowSetup setup = run_tsm(in, {{"focus", "1.0"}});
    ASSERT_FALSE(setup.fallbacks.empty());
    EXPECT_TRUE(has_note(setup.fallbacks, NoteKind::focus_out_of_range)) << describe(setup.fallbacks);
    EXPECT_TRUE(run_tsm(in).fallbacks.empty());
}
