// Why a shadow is wrong: each cause of a misclassified pixel planted where its answer is known (a
// closed form or a scene built for it), the remedy each cause names measured to remove most of it,
// and on every shipped scene and method the causes' pixels adding up to the misclassified ones.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "metrics/diagnosis.hpp"
#include "metrics/pixel_evidence.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using shadowlab::testing::camera_20_units_above_the_origin;
using shadowlab::testing::shipped_scenes;
using shadowlab::testing::source_path;

namespace {

struct DiagnosedRun {
    MeasureContext context;
    Measurement measured;
    Diagnosis diagnosis;
};

// One run measured and diagnosed, its remedies measured when asked.
DiagnosedRun diagnosed(const Scene& scene, const std::string& method_name,
                       const std::map<std::string, std::string>& overrides, int resolution,
                       glm::ivec2 image = {320, 180}, bool remedies = true, double bias = -1.0) {
    const Method& method = method_or_throw(method_name);
    const Settings settings = resolve_settings(method.name, method.settings, overrides);
    DiagnosedRun r{prepare_measurement(scene, image.x, image.y), {}, {}};
    r.measured = measure(r.context, method, settings, resolution, bias);
    r.diagnosis =
        remedies ? diagnose(r.context, method, settings, resolution, bias, r.measured) : count_causes(r.measured.error);
    return r;
}

Scene shipped(const std::string& name) { return load_scene(source_path("data/scenes/" + name + ".json")); }

const CauseCount* cause(const Diagnosis& d, PixelCause kind) {
    for (const CauseCount& c : d.causes)
        if (c.kind == kind) return &c;
    return nullptr;
}

std::string listed(const Diagnosis& d) {
    std::string text;
    for (const CauseCount& c : d.causes)
        text += std::string(to_string(c.kind)) + " " + std::to_string(c.pixels) +
                (c.remedy ? " (" + c.remedy->change + ": removes " + std::to_string(c.remedy->removes) + ")" : "") +
                "; ";
    return text;
}

// The top cause is `kind`, and the remedy it names sets most of its pixels right.
void expect_top_cause_remedied(const DiagnosedRun& r, PixelCause kind) {
    ASSERT_FALSE(r.diagnosis.causes.empty()) << "nothing misclassified";
    EXPECT_EQ(r.diagnosis.causes.front().kind, kind) << listed(r.diagnosis);
    const CauseCount* c = cause(r.diagnosis, kind);
    ASSERT_NE(c, nullptr) << listed(r.diagnosis);
    ASSERT_TRUE(c->remedy) << listed(r.diagnosis);
    EXPECT_GT(c->remedy->removes, 0.5) << listed(r.diagnosis);
}

// A 40 x 40 ground under an overhead camera, the light `tilt_deg` off the vertical in the x-y plane.
Scene ground_and(double tilt_deg, std::vector<SceneObject> casters = {}, bool ground_casts = false) {
    Scene scene;
    SceneObject ground;
    ground.shape = Shape::plane;
    ground.size = {40, 1, 40};
    ground.casts = ground_casts;
    scene.objects = {ground};
    for (SceneObject& o : casters) scene.objects.push_back(o);
    const double tilt = glm::radians(tilt_deg);
    scene.light.direction = {std::sin(tilt), -std::cos(tilt), 0};
    scene.camera = camera_20_units_above_the_origin();
    return scene;
}

SceneObject box(glm::dvec3 position, glm::dvec3 size, double turn_deg = 0.0) {
    SceneObject b;
    b.position = position;
    b.size = size;
    b.rotation_deg = {0, turn_deg, 0};
    return b;
}

}  // namespace

// Closed form: a plane read at zero bias compares each point with its texel centre's depth, on the
// same plane: the points farther from the light than their texel's centre, half of them, read
// shadow, and every one of them is the plane's own surface: acne, nothing else.
TEST(Diagnosis, APlaneAtZeroBiasHasAcneOnHalfItsPixels) {
    const DiagnosedRun r = diagnosed(ground_and(40.0, {}, true), "uniform", {{"bias_slope", "0"}}, 256, {200, 200});
    const CauseCount* acne = cause(r.diagnosis, PixelCause::acne);
    ASSERT_NE(acne, nullptr) << listed(r.diagnosis);
    EXPECT_NEAR(acne->share, 0.5, 0.1) << listed(r.diagnosis);
    EXPECT_EQ(r.diagnosis.causes.size(), 1u) << listed(r.diagnosis);
    ASSERT_TRUE(acne->remedy);
    EXPECT_GT(acne->remedy->removes, 0.95) << acne->remedy->change;
}

// Planted: a shipped scene with every bias at 0.
TEST(Diagnosis, EveryBiasAtZeroGivesAcneFirst) {
    const DiagnosedRun r = diagnosed(shipped("box_on_plane"), "focused", {{"bias_slope", "0"}}, 1024);
    expect_top_cause_remedied(r, PixelCause::acne);
}

// Planted: the same scene at 64²: texels of many pixels each; the shadow's edges are wrong over a
// texel's width.
TEST(Diagnosis, ACoarseMapGivesUnderSampling) {
    const DiagnosedRun r = diagnosed(shipped("box_on_plane"), "focused", {}, 64);
    expect_top_cause_remedied(r, PixelCause::under_sampling);
}

// Closed form: a card 1 unit above the ground, the light 45° off the vertical, a constant bias of
// 2 along the light: every ground point in its shadow is moved past the card (to 1.41 above the
// ground), whose depth the unbiased read holds: peter panning. A quarter of the bias (0.5) keeps
// the card's shadow.
TEST(Diagnosis, ABiasLongerThanTheGapIsPeterPanning) {
    const DiagnosedRun r =
        diagnosed(ground_and(45.0, {box({0, 1.0, 0}, {1, 0.02, 6})}), "uniform", {}, 1024, {200, 200}, true, 2.0);
    expect_top_cause_remedied(r, PixelCause::peter_panning);
    const CauseCount* c = cause(r.diagnosis, PixelCause::peter_panning);
    ASSERT_NE(c, nullptr);
    // The card's shadow on the ground, 1 x 6 of the 23.1² the camera sees.
    EXPECT_NEAR(c->share, 6.0 / (23.09 * 23.09), 0.003) << listed(r.diagnosis);
}

// Closed form: light 80° off the vertical on a ground seen from above, the map's texels sized by
// a tall pole across the light: a texel's image on the ground is stretched up to 1 / cos 80° ≈
// 5.8 times by the ground's tilt to the light alone, and the wrong pixels at the box's shadow
// edges are projection aliasing.
TEST(Diagnosis, GrazingLightGivesProjection) {
    const DiagnosedRun r =
        diagnosed(ground_and(80.0, {box({0, 0.5, 0}, {2, 1, 2}, 30), box({-15, 10, 15}, {1, 20, 1})}), "uniform", {},
                  512, {320, 320});
    EXPECT_GT(r.measured.error.m_projection.p95, 3.0);
    expect_top_cause_remedied(r, PixelCause::projection);
}

// Planted: an engine's map (the custom method) covering half of what the focused map covers.
TEST(Diagnosis, AMapCoveringHalfTheViewGivesOutsideMap) {
    const Scene scene = shipped("box_on_plane");
    const Method& focused = method_or_throw("focused");
    const ShadowSetup setup = focused.compute_maps(gather_inputs(scene.camera, scene.light, object_boxes(scene)),
                                                   resolve_settings("focused", focused.settings, {}), nullptr);
    // u' = 2u - 1: the left half of the focused map's square is off the map.
    glm::dmat4 uvz = setup.maps.at(0).world_to_uvz;
    uvz = glm::dmat4(glm::dvec4(2, 0, 0, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, 1, 0), glm::dvec4(-1, 0, 0, 1)) *
          uvz;
    std::string columns;  // the clip matrix an engine would give: clip = 2 uvz - w for x, y, z
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row) {
            const double w = uvz[c][3], clip = row == 3 ? w : 2.0 * uvz[c][row] - w;
            char number[32];
            std::snprintf(number, sizeof number, "%.17g", clip);
            columns += (columns.empty() ? "" : ", ") + std::string(number);
        }
    const std::string file = ::testing::TempDir() + "diagnosis_half_map.glsl";
    std::ofstream(file) << "const mat4 lightViewProjection = mat4(" << columns << ");\n";
    const DiagnosedRun r = diagnosed(scene, "custom", {{"matrices", file}}, 1024);
    expect_top_cause_remedied(r, PixelCause::outside_map);
}

// Planted: a 16-bit map over a depth range of 1e5: a speck of a caster 1e5 along the light from the
// lone box stretches the focused map's depths to it, so one 16-bit step spans 1.5 world units, and
// the box's faces lit by the light read their own depth rounded by up to half of that: false
// shadow decided within one step. A 32-bit float map removes most of it.
TEST(Diagnosis, ASixteenBitMapOverADepthRangeOf1e5GivesDepthPrecision) {
    Scene scene = shipped("box_on_plane");
    SceneObject speck;
    speck.shape = Shape::sphere;
    speck.radius = 0.01;
    speck.position = -1e5 * glm::normalize(scene.light.direction);
    speck.receives = false;
    scene.objects.push_back(speck);
    const DiagnosedRun r = diagnosed(scene, "focused", {{"depth_format", "unorm16"}}, 1024);
    EXPECT_GT(r.measured.error.depth_step.p95, 1.0);  // world units per step
    expect_top_cause_remedied(r, PixelCause::depth_precision);
}

// Planted: cascades with no blend band: pixels beside a boundary between two cascades' pixels
// that the other cascade reads right.
TEST(Diagnosis, CascadesWithoutABlendBandShowSeams) {
    const DiagnosedRun r = diagnosed(shipped("default"), "cascades", {{"blend", "0"}}, 512, {1280, 720});
    const CauseCount* seam = cause(r.diagnosis, PixelCause::seam);
    ASSERT_NE(seam, nullptr) << listed(r.diagnosis);
    EXPECT_GT(seam->pixels, 10u) << listed(r.diagnosis);
    ASSERT_TRUE(seam->remedy);
    EXPECT_GT(seam->remedy->removes, 0.5) << listed(r.diagnosis);
}

// Closed form: a PCF kernel 8 texels wide over a bar's shadow 2 texels wide lights its whole
// width, where the one-texel read shadows it: the filter's error.
TEST(Diagnosis, AKernelWiderThanTheShadowIsTheFilters) {
    const DiagnosedRun r = diagnosed(ground_and(30.0, {box({0, 1.0, 0}, {0.16, 0.1, 20}, 20)}), "uniform",
                                     {{"filter", "pcf"}, {"filter_radius", "4"}}, 512, {200, 200});
    expect_top_cause_remedied(r, PixelCause::filter);
}

// Every misclassified pixel of every shipped scene and method gets exactly one cause, and the tests
// decide nearly all: undecided stays under a tenth of them.
TEST(Diagnosis, CausesAddUpToTheMisclassifiedPixelsEverywhere) {
    const std::vector<std::string> scenes = shipped_scenes();
    ASSERT_GT(scenes.size(), 10u);
    size_t runs = 0, wrong = 0, undecided = 0;
    for (const std::string& file : scenes) {
        const MeasureContext context = prepare_measurement(load_scene(file), 160, 90);
        for (const Method& method : all_methods()) {
            const Settings settings = resolve_settings(method.name, method.settings, {});
            const Measurement m = measure(context, method, settings, 512, -1.0);
            const ShadowError& e = m.error;
            ASSERT_EQ(e.causes.size(), e.verdicts.size());
            size_t misclassified = 0;
            for (size_t i = 0; i < e.verdicts.size(); ++i) {
                const bool is_wrong =
                    e.verdicts[i] == PixelVerdict::false_shadow || e.verdicts[i] == PixelVerdict::false_light;
                misclassified += is_wrong;
                EXPECT_EQ(is_wrong, e.causes[i] != PixelCause::none) << file << " " << method.name << " pixel " << i;
            }
            const Diagnosis d = count_causes(e);
            EXPECT_EQ(d.misclassified, misclassified) << file << " " << method.name;
            double shares = 0.0;
            for (const CauseCount& c : d.causes) shares += c.share;
            EXPECT_NEAR(shares, e.misclassified, 1e-9) << file << " " << method.name;
            if (const CauseCount* u = cause(d, PixelCause::undecided)) undecided += u->pixels;
            wrong += misclassified;
            ++runs;
        }
    }
    EXPECT_GT(runs, 100u);
    EXPECT_GT(wrong, 1000u);
    EXPECT_LT(double(undecided), 0.1 * double(wrong)) << undecided << " of " << wrong;
}

// The table: every cause named once, `undecided` last and always holding, the order the precedence.
TEST(Diagnosis, TheCauseTableDecidesByItsOrder) {
    const std::vector<CauseInfo>& causes = all_causes();
    ASSERT_GE(causes.size(), 10u);
    EXPECT_EQ(causes.back().kind, PixelCause::undecided);
    for (size_t i = 0; i < causes.size(); ++i)
        for (size_t j = i + 1; j < causes.size(); ++j) EXPECT_STRNE(causes[i].name, causes[j].name);
    PixelEvidence acne_in_band{.false_shadow = true, .seam = true, .gap = 1.0, .step = 1e-7, .own_surface = true};
    EXPECT_EQ(cause_of(acne_in_band), PixelCause::seam);  // the seam comes first
    acne_in_band.seam = false;
    EXPECT_EQ(cause_of(acne_in_band), PixelCause::acne);
    acne_in_band.gap = 0.5e-7;  // within one step of the format: precision before acne
    EXPECT_EQ(cause_of(acne_in_band), PixelCause::depth_precision);
    EXPECT_EQ(cause_of(PixelEvidence{.reads_map = false}), PixelCause::outside_map);
    EXPECT_EQ(
        cause_of(PixelEvidence{.false_shadow = true, .gap = 1, .straddles_edge = true, .projection_dominant = true}),
        PixelCause::projection);
}
