#pragma once
// `shadowlab measure SCENE --method M --resolution N [--size WxH] [--bias B] [--set k=v]... [--json]`
#include <map>
#include <string>

namespace shadowlab {

struct MeasureOptions {
    std::string scene_file;
    std::string method = "focused";
    std::map<std::string, std::string> settings;
    int resolution = 1024;
    int width = 1280, height = 720;
    double bias = -1.0;  // world units along the light; < 0: 2e-4 of the scene's diagonal
    bool json = false;
};

// Prints the metrics to stdout and progress to stderr; throws on bad input.
void run_measure(const MeasureOptions& options);

}  // namespace shadowlab
