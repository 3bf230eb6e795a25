#pragma once
// Starts the inspector window on a scene; returns the application's exit code.
#include <string>

namespace shadowlab {

struct InspectorOptions {
    std::string scene_file;
    std::string screenshot;  // when set: write the window to this PNG once drawn, then quit
    int width = 1600, height = 1000;
};

// Throws std::runtime_error when no X display can be opened.
int run_inspector(int argc, char** argv, const InspectorOptions& options);

}  // namespace shadowlab
