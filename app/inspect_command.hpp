#pragma once
// `shadowlab inspect SCENE [--method NAME] [--set key=value]... [--json]`
#include <map>
#include <string>

#include "scene_source.hpp"

namespace shadowlab {

struct InspectOptions {
    std::string scene_file;
    SceneSource scene_source;  // which of the scene file's cameras and lights, or an engine's camera
    std::string method = "focused";
    std::map<std::string, std::string> settings;
    bool json = false;
};

// Prints the inspection to stdout; throws on bad input (the caller prints one line and exits 1).
void run_inspect(const InspectOptions& options);

}  // namespace shadowlab
