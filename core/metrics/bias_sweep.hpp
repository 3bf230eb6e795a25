#pragma once
// The acne / peter-panning trade-off of a depth bias: one map method measured at a ladder of values
// of one bias setting (lookup/lookup_settings.hpp). Too little bias and a lit surface shadows itself
// (acne: false shadow); too much and shadows come off their casters or leak (peter panning: false
// light). The best value is where their sum, the misclassified share, is least.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "metrics/measurement.hpp"

namespace shadowlab {

// The bias settings a sweep can run over.
inline const std::vector<std::string> kBiasSettings{"bias_slope", "bias_normal", "bias_constant"};

struct BiasPoint {
    double value = 0.0;                                                 // of the swept setting, in its own unit
    double false_shadow = 0.0, false_light = 0.0, misclassified = 0.0;  // shares of receiver pixels
    std::vector<Note> fallbacks;
};

struct BiasCurve {
    std::string method, setting;
    std::map<std::string, std::string> settings;  // the method's settings as measured, the swept one left out
    std::vector<BiasPoint> points;                // in the order of the values given
    size_t best = 0;  // the point of least misclassified share; of equals, the smallest value
};

// Called after each value is measured: the point, and how many of how many are done.
using BiasProgress = std::function<void(const BiasPoint& point, size_t done, size_t count)>;

// The settings a sweep of `bias_setting` measures with, beside the swept value: `overrides`, and
// bias_slope=0 when sweeping bias_normal or bias_constant (unless overridden), so that the curve
// shows that bias alone and not its sum with the default slope-scaled bias. Throws
// std::invalid_argument for a setting not in kBiasSettings, or when `overrides` sets the swept one.
std::map<std::string, std::string> bias_sweep_settings(const std::map<std::string, std::string>& overrides,
                                                       const std::string& bias_setting);

// The values swept when none are given: 0, then a geometric ladder (two steps per doubling) over the
// range where the setting's acne gives way to peter panning.
//   bias_slope:    1/16 .. 32 times the slope-scaled bias;
//   bias_normal:   1/8 .. 8 texel widths;
//   bias_constant: 1/64 .. 64 texel widths, in world units. A texel's width here is the receivers'
//                  bounding box diagonal over `resolution`: the texel of a map stretched over every
//                  receiver, which a focused map's texels never exceed (it holds less of the scene).
//                  Acne needs a bias of about a texel's width times tan θ (θ between surface and
//                  light), up to ~114 widths at a 0.5° sun, so the ladder brackets it at any
//                  resolution. (The measured depth_step is one step of the map's depth format,
//                  not a texel's width: it sizes quantization, 2^-24 of the depth range for
//                  float32 near the far end or unorm24, far below any acne; unorm16's 2^-16 can
//                  reach it over a deep range.)
std::vector<double> default_bias_values(const MeasureContext& context, const std::string& bias_setting, int resolution);

// `method` (a map method) measured at `resolution` with bias_sweep_settings(overrides, bias_setting)
// and `bias_setting` at each of `values`: per value its false shadow, false light, misclassified
// share and fallbacks; and the best point.
BiasCurve sweep_bias(const MeasureContext& context, const Method& method,
                     const std::map<std::string, std::string>& overrides, int resolution,
                     const std::string& bias_setting, const std::vector<double>& values,
                     const BiasProgress& progress = {});

}  // namespace shadowlab
