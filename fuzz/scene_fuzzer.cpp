// libFuzzer target: the input as a scene file and, when the loader accepts it, every method of the
// registry on it, as `inspect` (traced) and `measure` (maps rasterized, every pixel judged) run
// them. A refusal (SceneError, naming file and field) is the right answer to bad input.
// A scene once accepted is the loader's promise that every method can compute it, so from there
// on any exception, crash, sanitizer report or non-finite map is a bug in core, not in the input.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <nlohmann/json.hpp>

#include "metrics/measurement.hpp"
#include "registry/method.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {
namespace {

// Caps that keep one input well under a second under the sanitizers: the methods see the first 32
// objects (the default town's 400 take seconds in the geometric techniques, yet its mutations
// still fuzz the loader whole); a tiny camera image and a small shadow-map texture.
constexpr std::size_t kMaxObjects = 32;
constexpr int kImageWidth = 8, kImageHeight = 6;
constexpr int kResolution = 64;
constexpr double kSlopeScaledBias = -1.0;  // measure's default

// A finding: libFuzzer keeps the input that led here.
[[noreturn]] void bug(const std::string& where, const std::string& what) {
    std::fprintf(stderr, "scene_fuzzer: %s: %s\n", where.c_str(), what.c_str());
    std::abort();
}

// The fuzzer reads no file but its input, so a scene with a mesh object is skipped before the
// loader would open the mesh. The JSON is parsed rather than searched: "m\u0065sh" names a mesh too.
bool names_a_mesh(const std::string& text) {
    const nlohmann::json scene = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    const auto objects = scene.is_object() ? scene.find("objects") : scene.end();
    if (objects == scene.end() || !objects->is_array()) return false;
    for (const nlohmann::json& object : *objects)
        if (object.is_object() && object.contains("type") && object["type"] == "mesh") return true;
    return false;
}

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

void run_every_method(const Scene& scene) {
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

}  // namespace
}  // namespace shadowlab

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace shadowlab;
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (names_a_mesh(text)) return 0;
    Scene scene;
    try {
        scene = parse_scene(text, "fuzz.json");
    } catch (const SceneError&) {
        return 0;
    }
    if (scene.objects.size() > kMaxObjects) scene.objects.resize(kMaxObjects);
    try {
        run_every_method(scene);
    } catch (const std::exception& error) {
        bug("an accepted scene", std::string("threw: ") + error.what());
    }
    return 0;
}
