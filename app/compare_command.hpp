#pragma once
// `shadowlab compare SCENE --methods A,B [--set k=v]... [--set-a k=v]... [--set-b k=v]...
//  [--resolution N] [--size WxH] [--bias B] --out DIR`
// Two configurations (two methods, or one method with two settings: --methods lispsm,lispsm
// --set-b filter=pcf) measured against one exact reference, side by side: DIR/difference.png (the
// Difference view: who is right where the verdicts differ), DIR/compare.json (each run as `measure
// --json` prints it, and the comparison's counts), DIR/compare.md (the two measures in one table)
// and DIR/lesson.html (the lesson's "What goes wrong" for each).
#include <map>
#include <string>
#include <vector>

#include "exchange/inspection_json.hpp"
#include "metrics/verdict_comparison.hpp"
#include "scene_source.hpp"

namespace shadowlab {

struct CompareOptions {
    std::string scene_file;
    SceneSource scene_source;
    std::vector<std::string> methods;                           // exactly two: A, B (may be the same)
    std::map<std::string, std::string> settings;                // both configurations
    std::map<std::string, std::string> settings_a, settings_b;  // one each, over `settings`
    int resolution = 1024;
    int width = 1280, height = 720;
    double bias = -1.0;  // world units along the light; < 0: the settings' (slope-scaled)
    std::string out;     // the directory; created if missing
};

// Writes the four files (needs X: xvfb-run, for the pictures) and returns compare.json's content.
// Throws std::invalid_argument, one line naming the option or the setting, on bad input.
Json run_compare(const CompareOptions& options);

// compare.json's "comparison": {"receiver_pixels", "both_right", "both_wrong", "only_a_right",
// "only_b_right", "differing"}.
Json to_json(const VerdictComparison& comparison);

}  // namespace shadowlab
