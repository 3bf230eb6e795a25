#include "shimmer_command.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "limits.hpp"
#include "plot/shimmer_chart.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {
namespace {

constexpr int kMaxFrames = 10000;

CameraPath path_or_throw(const ShimmerOptions& o) {
    const auto kind = camera_path_named(o.path);
    if (!kind) throw std::invalid_argument("--path: unknown '" + o.path + "' (one of translate, rotate, dolly)");
    if (o.frames < 2 || o.frames > kMaxFrames)
        throw std::invalid_argument("--frames: " + std::to_string(o.frames) + " is outside 2.." +
                                    std::to_string(kMaxFrames));
    if (!std::isfinite(o.step)) throw std::invalid_argument("--step: not a finite number");
    return {*kind, o.frames, o.step};
}

// The map method to follow and its settings; throws for a technique, a bad setting or resolution.
std::pair<const Method&, Settings> method_to_follow(const ShimmerOptions& o) {
    limits::check(limits::map_resolution, "--resolution", o.resolution);
    const Method& method = method_or_throw(o.method);
    if (!method.makes_maps())
        throw std::invalid_argument("--method: " + method.name + " is a geometric technique: it has no map to shimmer");
    return {method, resolve_settings(method.name, method.settings, o.settings)};
}

}  // namespace

Shimmer shimmer_on(const MeasureContext& context, const ShimmerOptions& o) {
    const CameraPath path = path_or_throw(o);
    const auto [method, settings] = method_to_follow(o);
    const std::vector<ShimmerSample> samples = shimmer_samples(context);
    std::cerr << "shimmer: " << method.name << ", " << samples.size() << " fixed receiver points, " << path.frames
              << " frames, " << to_string(path.kind) << " by " << step_per_frame(path, context.scene.camera)
              << (path.kind == CameraPath::Kind::rotate ? "° per frame\n" : " per frame\n");
    return measure_shimmer(context, samples, method, settings, o.resolution, -1.0, path);
}

void run_shimmer(const ShimmerOptions& o) {
    if (o.out_dir.empty()) throw std::invalid_argument("--out: a directory is required");
    const auto [method, settings] = method_to_follow(o);  // bad input stops before the reference is traced
    limits::check(limits::image_side, "--size width", o.width);
    limits::check(limits::image_side, "--size height", o.height);
    const CameraPath path = path_or_throw(o);
    const MeasureContext context =
        prepare_measurement(load_scene_source(o.scene_file, o.scene_source), o.width, o.height);
    const Shimmer shimmer = shimmer_on(context, o);

    const std::filesystem::path dir(o.out_dir);
    std::filesystem::create_directories(dir);
    std::ofstream csv(dir / "shimmer.csv");
    if (!csv) throw std::runtime_error((dir / "shimmer.csv").string() + ": cannot write");
    csv << "frame,judged,wrong,transitions,flips,pages_allocated,pages_kept,pages_freed,texels_fresh,texels_cached,"
           "fallback\n";
    for (const FrameShimmer& f : shimmer.frames)
        csv << f.frame << ',' << f.judged << ',' << f.wrong << ',' << f.transitions << ',' << f.flips << ','
            << f.pages.allocated << ',' << f.pages.kept << ',' << f.pages.freed << ',' << std::llround(f.texels_fresh)
            << ',' << std::llround(f.texels_cached) << ",\"" << describe(f.fallbacks) << "\"\n";
    csv.close();
    const std::string summary = shimmer_summary(shimmer);
    write_chart_png(shimmer_chart(shimmer, "Shimmer: " + method.name + ", camera " + to_string(path.kind) + ", " +
                                               std::to_string(o.resolution) + "², " + summary),
                    (dir / "shimmer.png").string());
    std::cout << "shimmer: " << method.name << ", " << to_string(path.kind) << ", " << path.frames
              << " frames: " << summary << "\ntexels drawn per frame: " << shimmer.texels_fresh_per_frame()
              << " fresh, " << shimmer.texels_cached_per_frame() << " with a page cache\nwrote "
              << (dir / "shimmer.csv").string() << " and " << (dir / "shimmer.png").string() << "\n";
}

}  // namespace shadowlab
