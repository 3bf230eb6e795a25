#pragma once
// What both lesson pages share (lesson_command.cpp's pictures, interactive_lesson.cpp's orbitable
// views): the inspection a lesson explains, which views show each step, and the page's HTML text:
// the head with the method's description, a step's values with matrices as 4 x 4 tables.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "io/value_text.hpp"
#include "lesson_command.hpp"
#include "views/space_parts.hpp"

namespace shadowlab {

struct Picture {
    const View* view;
    SpacePreset preset;
    std::string title;  // what the picture shows, under it
};

Inspection inspect_for_lesson(const LessonOptions& options);

// The pictures that show step `i`: its space from the side and from the light (an orbit for the
// world), both sides of the warp at the first step in PPLS, and the result after the last step.
std::vector<Picture> pictures_of(const Inspection& in, size_t i);

// A picture's size: the scene camera's aspect within the asked size for a view through the camera.
glm::ivec2 picture_size(const Inspection& in, const Picture& picture, const LessonOptions& options);

std::string html_escaped(const std::string& text);

// Where a page keeps a picture: given the image and a file name for it, the <img> element's src
// (the static page writes the file beside itself, the interactive page inlines it as a data URI).
using PictureSource = std::function<std::string(const RgbImage& image, const std::string& name)>;

// <figure> with the picture at `src` shown `width` pixels wide and its caption (also its alt text).
std::string picture_figure(const std::string& src, int width, const std::string& caption);

// The step's values, a matrix as a 4 x 4 table (4 significant digits shown, all 17 on hover).
std::string values_table(const Step& step, MatrixLayout layout);

// "Step 3 of 10: title", the formula, the space and the values.
std::string step_heading(const Step& step, size_t i, size_t count, MatrixLayout layout);

// <!DOCTYPE html> to the end of the introduction: the title, the method's description, the
// scene, the map's size, the notes. `style` is added to the pages' shared style sheet.
std::string page_head(const Inspection& in, const LessonOptions& options, MatrixLayout layout,
                      const std::string& style = "");

// A whole page in the lessons' style: `title`, then `body` (`shadowlab compare`'s lesson.html).
std::string lesson_page(const std::string& title, const std::string& body);

// Throws std::runtime_error naming the file when it cannot be written.
void write_text_file(const std::filesystem::path& file, const std::string& text);

}  // namespace shadowlab
