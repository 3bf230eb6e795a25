#pragma once
// The one error a scene (file or in-memory) can raise: it names the file, the JSON path of the
// offending field and what was expected, e.g.
//   data/scenes/x.json: objects[3].size: expected three positive numbers, got [1, -2, 1]
// in one line of valid UTF-8, whatever bytes of a binary file the problem quotes (printable_text).
#include <stdexcept>
#include <string>

#include "io/printable_text.hpp"

namespace shadowlab {

class SceneError : public std::runtime_error {
public:
    SceneError(std::string file, std::string json_path, std::string problem)
        : std::runtime_error(format(file, json_path, problem)),
          file_(std::move(file)),
          json_path_(std::move(json_path)),
          problem_(printable_text(problem)) {}

    const std::string& file() const { return file_; }
    const std::string& json_path() const { return json_path_; }
    const std::string& problem() const { return problem_; }

private:
    static std::string format(const std::string& file, const std::string& path, const std::string& problem) {
        std::string out = file.empty() ? std::string("<scene>") : file;
        if (!path.empty()) out += ": " + path;
        return printable_text(out + ": " + problem);
    }
    std::string file_, json_path_, problem_;
};

}  // namespace shadowlab
