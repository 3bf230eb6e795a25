// Truth at every scale (issue 11): the same scene moved far from the origin or scaled gives the
// same verdicts, for the exact reference, every map method and every geometric technique.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/measurement.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 200, kHeight = 120, kResolution = 1024;

// A small town under a low sun (or a point light), seen from its edge.
Scene town(LightType light) {
    Scene scene = random_town(40, 100.0, 7);
    scene.camera.position = {0.0, 6.0, 55.0};
    scene.camera.target = {0.0, 0.0, 0.0};
    scene.camera.aspect = double(kWidth) / kHeight;
    scene.camera.near = 0.5;
    scene.camera.far = 150.0;
    scene.light.type = light;
    scene.light.direction = glm::normalize(glm::dvec3(-0.6, -0.5, -0.4));
    scene.light.position = {30.0, 40.0, 20.0};
    return scene;
}

// x -> scale x + offset for every point, lengths times scale.
Scene moved(Scene scene, double scale, const glm::dvec3& offset) {
    for (SceneObject& o : scene.objects) {
        o.position = scale * o.position + offset;
        o.scale *= scale;
    }
    Camera& c = scene.camera;
    c.position = scale * c.position + offset;
    c.target = scale * c.target + offset;
    c.near *= scale;
    c.far *= scale;
    scene.light.position = scale * scene.light.position + offset;
    return scene;
}

// The share of pixels whose verdicts differ.
template <class T>
double differing(const std::vector<T>& a, const std::vector<T>& b) {
    size_t differ = 0;
    for (size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
    return double(differ) / double(a.size());
}

const std::vector<std::map<std::string, std::string>> kCascadeVariants{{{"stabilize", "on"}, {"fit", "sphere"}},
                                                                       {{"bounds", "visible"}, {"lambda", "1"}}};

// The lookups: each filter and the biases that read the map's derivatives, on the focused map (and
// PCF on a warp); a world-length kernel scales with the scene, and so do contact shadows' lengths.
std::vector<std::pair<std::string, std::map<std::string, std::string>>> lookup_variants(double scale) {
    return {{"focused", {{"filter", "pcf"}, {"pcf_kernel", "poisson"}, {"kernel_size", "4"}, {"filter_radius", "1.5"}}},
            {"lispsm", {{"filter", "pcf"}, {"pcf_kernel", "tent"}}},
            {"focused", {{"filter", "pcf"}, {"filter_world_radius", std::to_string(0.3 * scale)}}},
            {"focused", {{"filter", "vsm"}, {"bleed_reduction", "0.2"}}},
            {"focused", {{"filter", "evsm"}}},
            {"focused", {{"filter", "msm"}, {"msm_quantization", "unorm16"}}},
            {"focused", {{"filter", "esm"}}},
            {"focused", {{"filter", "pcss"}}},
            {"focused", {{"bias_slope", "0"}, {"bias_normal", "1"}, {"bias_receiver_plane", "on"}}},
            {"focused",
             {{"bias_normal", "8"},
              {"contact_length", std::to_string(0.5 * scale)},
              {"contact_thickness", std::to_string(0.1 * scale)}}}};
}

struct Verdicts {
    std::vector<uint8_t> visible, lit;
    std::vector<std::vector<PixelVerdict>> per_method;  // in the registry's order
};

// A method's default settings for a scene scaled by `scale`: settings with a unit of length scale too.
Settings scaled_defaults(const Method& m, double scale) {
    std::map<std::string, std::string> scaled;
    for (const SettingSpec& spec : m.settings)
        if (spec.length_power != 0)
            scaled[spec.name] = std::to_string(std::stod(spec.default_value) * std::pow(scale, spec.length_power));
    return resolve_settings(m.name, m.settings, scaled);
}

Verdicts verdicts(const Scene& scene, double scale) {
    const MeasureContext context = prepare_measurement(scene, kWidth, kHeight);
    Verdicts v{context.reference.visible, context.reference.lit, {}};
    for (const Method& m : all_methods())
        v.per_method.push_back(measure(context, m, scaled_defaults(m, scale), kResolution, -1.0).error.verdicts);
    // Settings whose results hang on the scene's place and size: stabilized cascades snap to a grid
    // anchored in the scene; visible bounds read the depth image.
    const Method& cascades = method_or_throw("cascades");
    for (const auto& set : kCascadeVariants)
        v.per_method.push_back(
            measure(context, cascades, resolve_settings("cascades", cascades.settings, set), kResolution, -1.0)
                .error.verdicts);
    for (const auto& [name, set] : lookup_variants(scale)) {
        const Method& m = method_or_throw(name);
        v.per_method.push_back(
            measure(context, m, resolve_settings(name, m.settings, set), kResolution, -1.0).error.verdicts);
    }
    return v;
}

class Invariance : public ::testing::TestWithParam<std::tuple<LightType, double, double>> {};

}  // namespace

// Verdicts may differ only where rounding decides: pixels on a shadow edge, a few in ten thousand.
TEST_P(Invariance, MovedAndScaledSceneKeepsItsVerdicts) {
    const auto [light, scale, offset] = GetParam();
    const Scene here = town(light);
    const Verdicts expected = verdicts(here, 1.0);
    const Verdicts got = verdicts(moved(here, scale, glm::dvec3(offset, 0.25 * offset, -offset)), scale);
    EXPECT_EQ(differing(expected.visible, got.visible), 0.0) << "the reference sees other points";
    EXPECT_LE(differing(expected.lit, got.lit), 5e-4) << "the reference lights other points";
    for (size_t k = 0; k < expected.per_method.size(); ++k)
        EXPECT_LE(differing(expected.per_method[k], got.per_method[k]), 5e-4)
            << (k < all_methods().size()
                    ? all_methods()[k].name
                    : "variant " + std::to_string(k - all_methods().size()) + " (cascades, then the lookups)");
}

std::string configuration_name(const ::testing::TestParamInfo<Invariance::ParamType>& info) {
    const auto [light, scale, offset] = info.param;
    const int decade = int(std::lround(std::log10(scale)));
    return std::string(to_string(light)) + "_scale_1e" + (decade < 0 ? "minus" : "") +
           std::to_string(std::abs(decade)) +
           (offset > 0.0 ? "_offset_1e" + std::to_string(int(std::lround(std::log10(offset)))) : "_at_origin");
}

INSTANTIATE_TEST_SUITE_P(Scenes, Invariance,
                         ::testing::Combine(::testing::Values(LightType::directional, LightType::point),
                                            ::testing::Values(1e-3, 1.0, 1e4), ::testing::Values(0.0, 1e3, 1e6, 1e7)),
                         configuration_name);
