#pragma once
// `shadowlab shimmer SCENE --method M [--set k=v]... [--path translate|rotate|dolly] [--frames N]
//  [--step S] [--resolution N] [--size WxH] --out DIR`: the camera moved along a path over the
// static scene; fixed receiver points judged every frame. DIR/shimmer.csv (per frame: points
// judged, wrong, transitions, flips, a virtual map's pages allocated, kept and freed, the texels drawn
// fresh and with a page cache) and DIR/shimmer.png (the share flipped and the share wrong per
// frame); the total share of flipped transitions on stdout.
#include <map>
#include <string>

#include "metrics/shimmer.hpp"
#include "scene_source.hpp"

namespace shadowlab {

struct ShimmerOptions {
    std::string scene_file;
    SceneSource scene_source;  // which of the scene file's cameras and lights, or an engine's camera
    std::string method = "focused";
    std::map<std::string, std::string> settings;
    std::string path = "translate";
    int frames = 60;
    double step = 0.0;  // per frame: world units (translate, dolly) or degrees (rotate); 0: automatic
    int resolution = 1024;
    int width = 640, height = 360;
    std::string out_dir;
};

// The method of `options` followed along its path from `context`'s camera (its scene file, size and
// out are not read); throws on bad input, a geometric technique among it. The Python module's
// shimmer is this call.
Shimmer shimmer_on(const MeasureContext& context, const ShimmerOptions& options);

void run_shimmer(const ShimmerOptions& options);

}  // namespace shadowlab
