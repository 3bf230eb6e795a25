#pragma once
// Starts the inspector window on a scene; returns the application's exit code.
#include <string>
#include <vector>

namespace shadowlab {

struct InspectorOptions {
    std::string scene_file;
    std::string screenshot;  // when set: write the window to this PNG once drawn, then quit
    // Two method names, A and B: the window opens in compare mode with A in the Controls and B in
    // the Compare dock (View > Compare); empty: one configuration.
    std::vector<std::string> compare;
    int width = 1600, height = 1000;
};

// Throws std::runtime_error when no X display can be opened.
int run_inspector(int argc, char** argv, const InspectorOptions& options);

}  // namespace shadowlab
