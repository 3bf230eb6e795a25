// shadowlab: the inspector's command line. Sub-commands run headless; with none, the default
// scene is inspected (the GUI takes this place once the viewer lands).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <CLI/CLI.hpp>

#include "inspect_command.hpp"
#include "measure_command.hpp"

namespace {

// The bundled scene: next to the sources in a build tree, or ./data from the repository root.
std::string default_scene() {
    for (const std::filesystem::path dir : {std::filesystem::path(SHADOWLAB_DATA_DIR), std::filesystem::path("data")})
        if (std::filesystem::exists(dir / "scenes/default.json")) return (dir / "scenes/default.json").string();
    return "data/scenes/default.json";
}

// "key=value" pairs into a map; throws CLI::ValidationError on a missing '='.
std::map<std::string, std::string> parse_settings(const std::vector<std::string>& pairs) {
    std::map<std::string, std::string> out;
    for (const std::string& pair : pairs) {
        const auto eq = pair.find('=');
        if (eq == std::string::npos || eq == 0)
            throw CLI::ValidationError("--set", "expected key=value, got '" + pair + "'");
        out[pair.substr(0, eq)] = pair.substr(eq + 1);
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"ShadowLab: an inspector for shadow-map parameterizations"};
    app.require_subcommand(0, 1);

    shadowlab::InspectOptions inspect;
    std::vector<std::string> set_pairs;
    CLI::App* inspect_cmd = app.add_subcommand("inspect", "print a method's steps, matrices and fallbacks for a scene");
    inspect_cmd->add_option("scene", inspect.scene_file, "scene file (JSON)")->required();
    inspect_cmd->add_option("--method,-m", inspect.method, "uniform | focused")->capture_default_str();
    inspect_cmd->add_option("--set", set_pairs, "a method setting, key=value (repeatable)");
    inspect_cmd->add_flag("--json", inspect.json, "print one JSON object instead of text");

    shadowlab::MeasureOptions measure;
    std::vector<std::string> measure_pairs;
    std::string size = "1280x720";
    CLI::App* measure_cmd = app.add_subcommand("measure", "a method's error against the exact reference, and its cost");
    measure_cmd->add_option("scene", measure.scene_file, "scene file (JSON)")->required();
    measure_cmd->add_option("--method,-m", measure.method, "method name")->capture_default_str();
    measure_cmd->add_option("--resolution,-r", measure.resolution, "shadow map resolution (texels per side)")->capture_default_str();
    measure_cmd->add_option("--size", size, "camera image size WxH")->capture_default_str();
    measure_cmd->add_option("--bias", measure.bias, "depth bias in world units (default: 2e-4 of the scene diagonal)");
    measure_cmd->add_option("--set", measure_pairs, "a method setting, key=value (repeatable)");
    measure_cmd->add_flag("--json", measure.json, "print one JSON object");

    try {
        app.parse(argc, argv);
        if (app.got_subcommand(measure_cmd)) {
            measure.settings = parse_settings(measure_pairs);
            if (std::sscanf(size.c_str(), "%dx%d", &measure.width, &measure.height) != 2)
                throw CLI::ValidationError("--size", "expected WxH, got '" + size + "'");
            shadowlab::run_measure(measure);
            return 0;
        }
        if (app.got_subcommand(inspect_cmd)) {
            inspect.settings = parse_settings(set_pairs);
        } else {
            inspect.scene_file = default_scene();
        }
        shadowlab::run_inspect(inspect);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::cerr << "shadowlab: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
