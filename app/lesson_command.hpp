#pragma once
// `shadowlab lesson SCENE --method M [--set k=v]... [--resolution N] [--size WxH] [--row-vectors] [--interactive]
//  --out DIR`
// A course page: DIR/index.html and its pictures. For each step of the method, its number and title,
// the formula it applies, its values (matrices as 4 x 4 tables) and the views that show it, drawn
// by the same code as the window: the World view for steps in the world, Light space and PPLS from
// the light and from the side, both sides of the warp at the step that applies it, and for the last
// step the Camera, Shadow map and Error views. Then "What goes wrong": the run's misclassified
// pixels ranked by cause, each cause's meaning and its remedy measured (what it removes, what it
// adds), and the Error view coloured by cause. With --interactive, DIR/index.html alone: the steps'
// views to orbit in the browser, then What goes wrong (interactive_lesson.hpp).
#include <map>
#include <string>

#include "scene_source.hpp"

namespace shadowlab {

struct LessonOptions {
    std::string scene_file;
    SceneSource scene_source;  // which of the scene file's cameras and lights, or an engine's camera
    std::string method = "lispsm";
    std::map<std::string, std::string> settings;
    int resolution = 1024;
    int width = 640, height = 400;  // each picture
    bool row_vectors = false;       // matrices as the papers print them (the transpose of ours)
    std::string out;                // the directory; created if missing
    bool interactive = false;       // one self-contained page whose views orbit (interactive_lesson.hpp)
};

// Writes the page and its pictures (needs X: xvfb-run); returns the number of pictures (views). Throws on
// bad input, naming the option or the file.
int run_lesson(const LessonOptions& options);

}  // namespace shadowlab
