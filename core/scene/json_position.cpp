#include "scene/json_position.hpp"

#include <vector>

#include "scene/scene_error.hpp"

namespace shadowlab {
namespace {

using nlohmann::json;

// A SAX pass that only tracks where it is, so that a syntax error is reported with its line and
// column, and a number too large for a double (1e999; nlohmann refuses it) with its JSON path.
class JsonErrorLocator final : public nlohmann::json_sax<json> {
public:
    explicit JsonErrorLocator(const std::string& file) : file_(file) {}

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(false); }
    bool key(string_t& key) override {
        levels_.back().key = key;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_array() override { return close(); }

    bool parse_error(std::size_t, const std::string& token, const json::exception& error) override {
        if (error.id == 406)  // "number overflow": the only error with a known JSON path
            throw SceneError(file_, path(), "expected a finite number, got " + token);
        const std::string message = error.what();
        const std::string marker = "parse error at ";  // followed by "line L, column C: ..."
        const std::size_t at = message.find(marker);
        if (at == std::string::npos) throw SceneError(file_, "", "malformed JSON: " + message);
        throw SceneError(file_, "", "malformed JSON at " + message.substr(at + marker.size()));
    }

private:
    struct Level {
        bool array;
        std::size_t index = 0;  // arrays: the element being read
        std::string key;        // objects: the member being read
    };

    bool open(bool array) {
        levels_.push_back({array, 0, {}});
        return true;
    }
    bool close() {
        levels_.pop_back();
        return value();
    }
    bool value() {
        if (!levels_.empty() && levels_.back().array) ++levels_.back().index;
        return true;
    }
    std::string path() const {
        std::string out;
        for (const Level& level : levels_)
            out = level.array ? out + "[" + std::to_string(level.index) + "]" : join_path(out, level.key);
        return out;
    }

    const std::string& file_;
    std::vector<Level> levels_;
};

}  // namespace

std::string join_path(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

json parse_scene_json(const std::string& text, const std::string& file) {
    JsonErrorLocator locator(file);
    json::sax_parse(text, &locator);
    return json::parse(text);
}

}  // namespace shadowlab
