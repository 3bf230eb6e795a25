#pragma once
// `shadowlab inspect SCENE [--method NAME] [--set key=value]... [--json]`
#include <map>
#include <string>

namespace shadowlab {

struct InspectOptions {
    std::string scene_file;
    std::string method = "focused";
    std::map<std::string, std::string> settings;
    bool json = false;
};

// Prints the inspection to stdout; throws on bad input (the caller prints one line and exits 1).
void run_inspect(const InspectOptions& options);

}  // namespace shadowlab
