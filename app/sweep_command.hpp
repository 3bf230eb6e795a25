#pragma once
// `shadowlab sweep SCENE [--methods a,b] [--resolution N] [--size WxH] --out DIR`: the light swept
// from perpendicular to the view (γ = 90°) to parallel with it (γ = 1e-4°), and far/near from 10 to
// 1e7; DIR/sweep.csv and the plots DIR/sweep_angle.png and DIR/sweep_far_near.png (error against
// the swept value, one line per method, fallbacks marked).
// With --bias [--bias-setting S] [--set k=v]...: instead, each map method measured at a ladder of
// values of the depth bias setting S (bias_slope by default; metrics/bias_sweep.hpp); DIR/sweep_bias.csv
// and DIR/sweep_bias.png (false shadow and false light against the bias, the best point labelled),
// and per method its best value on stdout.
#include <map>
#include <string>
#include <vector>

#include "scene_source.hpp"

namespace shadowlab {

struct SweepOptions {
    std::string scene_file;
    SceneSource scene_source;          // which of the scene file's cameras and lights, or an engine's camera
    std::vector<std::string> methods;  // empty: all
    int resolution = 1024;
    int width = 480, height = 270;
    std::string out_dir;
    bool bias = false;                            // sweep a bias setting, not the light and far/near
    std::string bias_setting = "bias_slope";      // with `bias`: which
    std::map<std::string, std::string> settings;  // with `bias`: every method's other settings
};

void run_sweep(const SweepOptions& options);

}  // namespace shadowlab
