#pragma once
// `lesson --interactive`: one self-contained HTML page that opens offline (file://). Beside the
// list of steps, each step's formula and values, and its World, Light space and PPLS views as 3D
// scenes to orbit in the browser: the shapes the views draw, in their spaces, read back from the
// views as built (views/view_export.hpp) and drawn again by three.js (web/src/lesson.js, bundled at
// build time and inlined). Views that show pictures (Camera, Shadow map, Error) are inlined PNGs;
// "What goes wrong" (what_goes_wrong.hpp) follows the steps, as on the static page.
// `index.html?selftest` clicks every step and writes what each canvas drew into <pre id="selftest">
// (tests/interactive_lesson_test.py reads it in headless Chromium).
#include <filesystem>

#include "lesson_page.hpp"

namespace shadowlab {

// Writes the page; returns the number of views on it.
int write_interactive_lesson(const Inspection& in, const LessonOptions& options, MatrixLayout layout,
                             const std::filesystem::path& file);

}  // namespace shadowlab
