#include "every_method.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "metrics/measurement.hpp"
#include "registry/method.hpp"

namespace shadowlab::fuzzing {
namespace {

// Caps that keep one input well under a second under the sanitizers: the methods see the first 32
// objects (the default town's 400 take seconds in the geometric techniques, yet its mutations
// still fuzz the loader whole); a tiny camera image and a small shadow-map texture.
constexpr std::size_t kMaxObjects = 32;
constexpr int kImageWidth = 8, kImageHeight = 6;
constexpr int kResolution = 64;
constexpr double kSlopeScaledBias = -1.0;  // measure's default

bool finite(const ShadowMap& map) {
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            if (!std::isfinite(map.world_to_uvz[column][row])) return false;
    return std::isfinite(map.z_bias_scale);
}

void check_maps(const std::string& method, const ShadowSetup& setup) {
    if (setup.maps.empty()) bug(method, "no map");
    for (const ShadowMap& map : setup.maps)
        if (!finite(map)) bug(method, "a map with a non-finite entry");
}

}  // namespace

// A finding: libFuzzer keeps the input that led here.
void bug(const std::string& where, const std::string& what) {
    std::fprintf(stderr, "fuzzer: %s: %s\n", where.c_str(), what.c_str());
    std::abort();
}

void run_every_method(Scene scene) {
    if (scene.objects.size() > kMaxObjects) scene.objects.resize(kMaxObjects);
    const ShadowInputs inputs = gather_inputs(scene);
    const MeasureContext context = prepare_measurement(scene, kImageWidth, kImageHeight);
    for (const Method& method : all_methods()) {
        const Settings settings = resolve_settings(method.name, method.settings, {});
        Trace trace;  // the trace's own computations are fuzzed too
        if (method.makes_maps())
            check_maps(method.name, method.compute_maps(inputs, settings, &trace));
        else
            method.compute_geometry(scene, context.triangles, context.reference, settings, &trace);
        measure(context, method, settings, kResolution, kSlopeScaledBias);
    }
}

}  // namespace shadowlab::fuzzing
