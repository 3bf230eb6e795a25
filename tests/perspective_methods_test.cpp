// Known values and paper-specific behaviour of the perspective warps (PSM, LiSPSM, XPSM).
#include <gtest/gtest.h>

#include <numeric>

#include "methods/lispsm.hpp"
#include "registry/method.hpp"
#include "scene/scene_loader.hpp"
#include "step_values.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

struct Traced {
    ShadowSetup setup;
    Trace trace;
};

Traced run(const std::string& method, const ShadowInputs& in, const std::map<std::string, std::string>& set = {}) {
    const Method& m = *find_method(method);
    Traced r;
    r.setup = m.compute_maps(in, resolve_settings(method, m.settings, set), &r.trace);
    return r;
}

ShadowInputs scene_inputs(const std::string& name) {
    return gather_inputs(load_scene(source_path("data/scenes/" + name + ".json")));
}

}  // namespace

TEST(Lispsm, NOptMatchesTheFormula) {
    EXPECT_NEAR(lispsm_n(1.0, 1000.0, 1.0, 0.0), 1.0 + std::sqrt(1000.0), 1e-9);
    EXPECT_NEAR(lispsm_n(1.0, 1000.0, 1.0, 0.0), 32.62, 0.005);                           // the known value
    EXPECT_NEAR(lispsm_n(1.0, 1000.0, 0.5, 0.0), 2.0 * (1.0 + std::sqrt(1000.0)), 1e-9);  // / sin γ
    EXPECT_NEAR(lispsm_n(2.0, 50.0, 1.0, 1.0), 2.0, 1e-9);                                // η = 1: PSM's n = z_n
    EXPECT_TRUE(std::isinf(lispsm_n(1.0, 1000.0, 1.0, -1.0)));                            // η = -1: no warp
    EXPECT_GT(lispsm_n(1.0, 1000.0, 1.0, -0.5), lispsm_n(1.0, 1000.0, 1.0, 0.0));         // η orders the warp
}

TEST(Lispsm, WarpFadesSmoothlyToTheFocusedMapAsTheLightTurnsParallel) {
    Scene scene = random_town(100, 400.0, 4);
    scene.camera.position = {0, 3, 150};
    scene.camera.target = {0, 2, 100};
    const glm::dvec3 view = scene.camera.view_direction();
    const glm::dvec3 side = glm::normalize(glm::cross(view, glm::dvec3(1, 0, 0)));
    double previous_ratio = 0.0;
    for (double gamma : {1.0, 0.3, 0.1, 1e-2, 1e-3, 1e-4, 1e-5}) {
        scene.light.direction = std::cos(gamma) * view + std::sin(gamma) * side;
        const Traced r = run("lispsm", gather_inputs(scene));
        ASSERT_TRUE(r.setup.fallbacks.empty()) << "γ = " << gamma;
        const double ratio = step_value(r.trace, "n-opt", "n") / step_value(r.trace, "n-opt", "z_f");
        EXPECT_GT(ratio, previous_ratio) << "n grows relative to the body as γ shrinks";
        previous_ratio = ratio;
    }
    scene.light.direction = std::cos(1e-8) * view + std::sin(1e-8) * side;
    const ShadowInputs in = gather_inputs(scene);
    const Traced parallel = run("lispsm", in);
    ASSERT_FALSE(parallel.setup.fallbacks.empty());
    EXPECT_TRUE(has_note(parallel.setup.fallbacks, NoteKind::parallel_light));
    // Just before the fallback (n = 4e3 times the depth) the warp is already (almost) the focused map.
    scene.light.direction = std::cos(5e-7) * view + std::sin(5e-7) * side;
    const glm::dmat4 warped = run("lispsm", gather_inputs(scene)).setup.maps[0].world_to_uvz;
    for (const glm::dvec3& p : in.receiver_points()) {
        if (!in.frustum.contains(p)) continue;
        const glm::dvec3 a = world_to_uvz(parallel.setup.maps[0], p),
                         b = world_to_uvz(ShadowMap{.world_to_uvz = warped}, p);
        EXPECT_NEAR(glm::length(a - b), 0.0, 1e-3);
    }
}

TEST(Lispsm, EtaMinusOneIsTheFocusedMapWithoutAFallback) {
    const ShadowInputs in = scene_inputs("default");
    const Traced r = run("lispsm", in, {{"eta", "-1"}});
    EXPECT_TRUE(r.setup.fallbacks.empty());
    EXPECT_EQ(r.setup.maps[0].world_to_uvz, run("focused", in).setup.maps[0].world_to_uvz);
}

TEST(Xpsm, FocusRegionMapsExactlyOntoTheUnitSquare) {
    for (const char* name : {"default", "light_overhead", "casters_behind", "far_near_1e5"}) {
        const ShadowInputs in = scene_inputs(name);
        const Traced r = run("xpsm", in);
        ASSERT_TRUE(r.setup.fallbacks.empty()) << name;
        const glm::dmat4& m = r.setup.maps[0].world_to_uvz;
        // The caster and receiver points XPSM kept (w ≥ εW), through the final map.
        auto box_of = [&](const char* step, const char* shape) {
            Aabb box;
            for (const NamedGeometry& g : r.trace.find(step)->geometry)
                if (g.name == shape) box = std::get<Aabb>(g.geometry);
            return box;
        };
        const Aabb casters = box_of("xpsm-12", "PPLS CastersBox"), receivers = box_of("xpsm-12", "PPLS ReceiversBox");
        const Aabb focus = box_of("xpsm-14", "focus region");
        // Independently: the focus region's corners, taken back to world space, map to the unit square.
        const glm::dmat4 ppls_to_world = glm::inverse(m) * [&] {
            for (const NamedValue& v : r.trace.find("xpsm-15")->values)
                if (v.name == "UnitCubeTransform") return std::get<glm::dmat4>(v.value);
            return glm::dmat4(1.0);
        }();
        for (int corner = 0; corner < 4; ++corner) {
            const glm::dvec3 ppls{corner & 1 ? focus.max.x : focus.min.x, corner & 2 ? focus.max.y : focus.min.y,
                                  focus.min.z};
            const glm::dvec4 world_h = ppls_to_world * glm::dvec4(ppls, 1.0);
            const glm::dvec3 uvz = world_to_uvz(r.setup.maps[0], glm::dvec3(world_h) / world_h.w);
            EXPECT_NEAR(uvz.x, corner & 1 ? 1.0 : 0.0, 1e-9) << name;
            EXPECT_NEAR(uvz.y, corner & 2 ? 1.0 : 0.0, 1e-9) << name;
        }
        // The focus region is the xy intersection of the two PPLS boxes.
        EXPECT_DOUBLE_EQ(focus.min.x, std::max(casters.min.x, receivers.min.x));
        EXPECT_DOUBLE_EQ(focus.max.y, std::min(casters.max.y, receivers.max.y));
        EXPECT_NEAR(r.setup.maps[0].z_bias_scale, 1.0 / focus.extent().z, 1e-15);
    }
}

TEST(Xpsm, TraceFollowsThePapersStepsInOrder) {
    const Traced r = run("xpsm", scene_inputs("default"));
    std::vector<int> numbers;
    for (const Step& s : r.trace.steps())
        if (s.id.rfind("xpsm-", 0) == 0) numbers.push_back(std::stoi(s.id.substr(5)));
    std::vector<int> expected(18);
    std::iota(expected.begin(), expected.end(), 1);
    EXPECT_EQ(numbers, expected);
    EXPECT_EQ(r.trace.find("xpsm-5")->title, "maxLengthP");
}

TEST(Xpsm, MinersLampIsANamedFallback) {
    const Traced r = run("xpsm", scene_inputs("light_parallel_behind"));
    ASSERT_FALSE(r.setup.fallbacks.empty());
    EXPECT_TRUE(has_note(r.setup.fallbacks, NoteKind::miners_lamp));
    EXPECT_LT(step_value(r.trace, "xpsm-3", "abs_V_xy"), 0.1);
}

TEST(Xpsm, LengthPIsClippedWhenCastersLieBehindTheViewer) {
    const Traced r = run("xpsm", scene_inputs("casters_behind"), {{"coef", "1"}});
    EXPECT_EQ(step_value(r.trace, "xpsm-7", "clipped"), 1.0);
    EXPECT_DOUBLE_EQ(step_value(r.trace, "xpsm-7", "lengthP"), step_value(r.trace, "xpsm-5", "maxLengthP"));
}

TEST(Psm, KozlovsRemediesAreNamedSteps) {
    const Traced behind = run("psm", scene_inputs("casters_behind"));
    EXPECT_GT(step_value(behind.trace, "psm-virtual-camera", "slide"), 0.0) << "casters behind: camera slid back";
    EXPECT_EQ(behind.trace.find("psm-light-frustum")->title, "Inverted projection (Kozlov)");
    const Traced front = run("psm", scene_inputs("default"));
    EXPECT_EQ(step_value(front.trace, "psm-light-frustum", "inverted"), 0.0);
    const Traced overhead = run("psm", scene_inputs("light_overhead"));
    EXPECT_NEAR(step_value(overhead.trace, "psm-light", "w_over_length"), 0.0, 1e-9);  // directional in PPS
    EXPECT_EQ(overhead.trace.find("psm-light-frustum"), nullptr);
}

TEST(PerspectiveMethods, WarpsMoveTexelsTowardTheViewer) {
    // Texel density |det d(u,v)/d(x,z)| on the ground near the viewer over that far away: about 1 for
    // the focused map, larger for every warp (that is what a warp is for).
    const ShadowInputs in = scene_inputs("light_overhead");
    const glm::dvec3 foot{in.camera.position.x, 0.0, in.camera.position.z};
    const glm::dvec3 ahead = glm::normalize(glm::dvec3(in.camera.view_direction().x, 0, in.camera.view_direction().z));
    const glm::dvec3 near_point = foot + 15.0 * ahead, far_point = foot + 120.0 * ahead;
    ASSERT_TRUE(in.frustum.contains(near_point) && in.frustum.contains(far_point));
    auto density = [](const ShadowMap& map, const glm::dvec3& p) {
        const double h = 1e-3;
        const glm::dvec3 a = world_to_uvz(map, p), bx = world_to_uvz(map, p + glm::dvec3(h, 0, 0)),
                         bz = world_to_uvz(map, p + glm::dvec3(0, 0, h));
        return std::abs(glm::determinant(glm::dmat2(glm::dvec2(bx - a), glm::dvec2(bz - a)))) / (h * h);
    };
    auto near_over_far = [&](const std::string& method) {
        const ShadowMap map = run(method, in).setup.maps[0];
        return density(map, near_point) / density(map, far_point);
    };
    const double focused = near_over_far("focused");
    EXPECT_NEAR(focused, 1.0, 1e-6);
    for (const char* method : {"psm", "lispsm", "xpsm"}) EXPECT_GT(near_over_far(method), 4.0 * focused) << method;
}

TEST(PerspectiveMethods, BiasScaleMovesAPointByTheBiasAlongTheLight) {
    // (d_pre - z_bias_scale * b) / w must equal the depth of the point moved b toward the light:
    // exactly for maps whose w is constant along light rays, at the visible region's centre for PSM.
    const ShadowInputs in = scene_inputs("default");
    for (const char* method : {"focused", "psm", "lispsm", "tsm", "xpsm"}) {
        const Traced r = run(method, in);
        const ShadowMap& map = r.setup.maps[0];
        const Step* visible = r.trace.find("visible");
        ASSERT_NE(visible, nullptr);
        const glm::dvec3 p = std::get<ConvexPolyhedron>(visible->geometry[0].geometry).centroid();
        const double b = 0.01;
        const glm::dvec4 h = map.world_to_uvz * glm::dvec4(p, 1.0);
        const double biased = (h.z - map.z_bias_scale * b) / h.w;
        const double moved = world_to_uvz(map, p - b * in.light.direction).z;
        EXPECT_NEAR(biased, moved, 1e-3 * std::abs(world_to_uvz(map, p).z - moved)) << method;
    }
}
