#pragma once
// `shadowlab lesson SCENE --method M [--set k=v]... [--resolution N] [--size WxH] [--row-vectors] --out DIR`
// A course page: DIR/index.html and its pictures. For each step of the method, its number and title,
// the formula it applies, its values (matrices as 4 x 4 tables) and the views that show it, drawn
// by the same code as the window: the World view for steps in the world, Light space and PPLS from
// the light and from the side, both sides of the warp at the step that applies it, and for the last
// step the Camera, Shadow map and Error views. Then "What goes wrong": the run's misclassified
// pixels ranked by cause, each cause's meaning and its remedy measured (what it removes, what it
// adds), and the Error view coloured by cause.
#include <filesystem>
#include <map>
#include <string>

#include "metrics/diagnosis.hpp"
#include "model/inspection.hpp"
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
};

// The "What goes wrong" section of a run measured on `context` (`run`, its `diagnosis`): its
// misclassified pixels ranked by cause, each cause's meaning and measured remedy, and the Error view
// by cause of `in` written to picture.file. `shadowlab compare` writes one per configuration.
struct WrongPicture {
    std::string id, heading;     // the section's HTML id and its title
    std::filesystem::path file;  // the PNG written; the page refers to it by its file name
    int width = 640, height = 400;
};
std::string what_goes_wrong_section(const Inspection& in, const MeasureContext& context, const Measurement& run,
                                    const Diagnosis& diagnosis, const WrongPicture& picture);
// A whole HTML page in the lesson's style around `body`.
std::string lesson_page(const std::string& title, const std::string& body);

// Writes the page and its pictures (needs X: xvfb-run); returns the number of pictures. Throws on
// bad input, naming the option or the file.
int run_lesson(const LessonOptions& options);

}  // namespace shadowlab
