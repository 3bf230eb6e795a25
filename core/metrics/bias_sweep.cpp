#include "metrics/bias_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/value_text.hpp"

namespace shadowlab {
namespace {

constexpr int kStepsPerDoubling = 2;  // a ladder step of √2: fine enough to find the best within ~20 %

// 0, then first, first·√2, ... up to last (both powers of two apart).
std::vector<double> zero_and_ladder(double first, double last) {
    std::vector<double> values{0.0};
    const int steps = int(std::lround(kStepsPerDoubling * std::log2(last / first)));
    for (int k = 0; k <= steps; ++k) values.push_back(first * std::exp2(double(k) / kStepsPerDoubling));
    return values;
}

void check_bias_setting(const std::string& setting) {
    if (std::find(kBiasSettings.begin(), kBiasSettings.end(), setting) == kBiasSettings.end())
        throw std::invalid_argument("bias setting '" + setting +
                                    "': expected bias_slope, bias_normal or bias_constant");
}

// The world width of a texel of a map stretched over every receiver (default_bias_values).
double receivers_texel_width(const MeasureContext& context, int resolution) {
    Aabb receivers;
    for (const ObjectBox& object : context.boxes)
        if (object.receives) receivers.extend(object.box);
    return receivers.diagonal() / resolution;
}

}  // namespace

std::map<std::string, std::string> bias_sweep_settings(const std::map<std::string, std::string>& overrides,
                                                       const std::string& bias_setting) {
    check_bias_setting(bias_setting);
    if (overrides.count(bias_setting))
        throw std::invalid_argument("setting " + bias_setting + ": it is the one swept; leave it out of --set");
    std::map<std::string, std::string> settings = overrides;
    if (bias_setting != "bias_slope") settings.try_emplace("bias_slope", "0");
    return settings;
}

std::vector<double> default_bias_values(const MeasureContext& context, const std::string& bias_setting,
                                        int resolution) {
    check_bias_setting(bias_setting);
    if (bias_setting == "bias_slope") return zero_and_ladder(1.0 / 16, 32.0);
    if (bias_setting == "bias_normal") return zero_and_ladder(1.0 / 8, 8.0);
    const double texel = receivers_texel_width(context, resolution);
    return zero_and_ladder(texel / 64, texel * 64);
}

BiasCurve sweep_bias(const MeasureContext& context, const Method& method,
                     const std::map<std::string, std::string>& overrides, int resolution,
                     const std::string& bias_setting, const std::vector<double>& values, const BiasProgress& progress) {
    if (!method.makes_maps()) throw std::invalid_argument(method.name + " has no map and so no depth bias");
    if (values.empty()) throw std::invalid_argument("a bias sweep needs at least one value");
    BiasCurve curve{
        .method = method.name, .setting = bias_setting, .settings = bias_sweep_settings(overrides, bias_setting)};
    for (double value : values) {
        std::map<std::string, std::string> settings = curve.settings;
        settings[bias_setting] = significant(value, kFullDigits);
        const Measurement m =
            measure(context, method, resolve_settings(method.name, method.settings, settings), resolution, -1.0);
        curve.points.push_back({.value = value,
                                .false_shadow = m.error.false_shadow,
                                .false_light = m.error.false_light,
                                .misclassified = m.error.misclassified,
                                .fallbacks = m.fallbacks});
        if (progress) progress(curve.points.back(), curve.points.size(), values.size());
    }
    const auto better = [](const BiasPoint& a, const BiasPoint& b) {
        return a.misclassified != b.misclassified ? a.misclassified < b.misclassified : a.value < b.value;
    };
    curve.best = size_t(std::min_element(curve.points.begin(), curve.points.end(), better) - curve.points.begin());
    return curve;
}

}  // namespace shadowlab
