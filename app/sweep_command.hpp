#pragma once
// `shadowlab sweep SCENE [--methods a,b] [--resolution N] [--size WxH] --out DIR`: the light swept
// from perpendicular to the view (γ = 90°) to parallel with it (γ = 1e-4°), and far/near from 10 to
// 1e7; DIR/sweep.csv and the plots DIR/sweep_angle.png and DIR/sweep_far_near.png (error against
// the swept value, one line per method, fallbacks marked).
#include <string>
#include <vector>

namespace shadowlab {

struct SweepOptions {
    std::string scene_file;
    std::vector<std::string> methods;  // empty: all
    int resolution = 1024;
    int width = 480, height = 270;
    std::string out_dir;
};

void run_sweep(const SweepOptions& options);

}  // namespace shadowlab
