// shadowlab: the inspector. With no sub-command it opens the window on the default scene (or, with
// no X display, prints the default scene's inspection); sub-commands run headless.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <CLI/CLI.hpp>

#include "bench_command.hpp"
#include "compare_command.hpp"
#include "filter_bench.hpp"
#include "gui/inspector_app.hpp"
#include "inspect_command.hpp"
#include "lesson_command.hpp"
#include "measure_command.hpp"
#include "metrics/bias_sweep.hpp"
#include "registry/method.hpp"
#include "render_command.hpp"
#include "shimmer_command.hpp"
#include "sweep_command.hpp"
#include "views/view.hpp"

namespace {

// The bundled scene: next to the sources in a build tree, or ./data from the repository root.
std::string default_scene() {
    for (const std::filesystem::path& dir : {std::filesystem::path(SHADOWLAB_DATA_DIR), std::filesystem::path("data")})
        if (std::filesystem::exists(dir / "scenes/default.json")) return (dir / "scenes/default.json").string();
    return "data/scenes/default.json";
}

// "key=value" pairs into a map; throws CLI::ValidationError, naming `option`, on a missing '='.
std::map<std::string, std::string> parse_settings(const std::vector<std::string>& pairs,
                                                  const std::string& option = "--set") {
    std::map<std::string, std::string> out;
    for (const std::string& pair : pairs) {
        const auto eq = pair.find('=');
        if (eq == std::string::npos || eq == 0)
            throw CLI::ValidationError(option, "expected key=value, got '" + pair + "'");
        out[pair.substr(0, eq)] = pair.substr(eq + 1);
    }
    return out;
}

// "WxH" into two numbers; throws CLI::ValidationError otherwise.
void parse_size(const std::string& text, int& width, int& height) {
    char end = 0;
    if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &end) != 2)
        throw CLI::ValidationError("--size", "expected WxH, got '" + text + "'");
}

// Which of a scene file's cameras and lights the command takes (a glTF file may hold several), or
// an engine's camera in place of the file's.
void add_scene_source(CLI::App* command, shadowlab::SceneSource& source) {
    command
        ->add_option("--camera-index", source.choice.camera,
                     "the scene file's camera to take, 0-based (glTF: cameras[N])")
        ->capture_default_str();
    command
        ->add_option("--light-index", source.choice.light,
                     "the scene file's light to take, 0-based (glTF: KHR_lights_punctual's lights[N])")
        ->capture_default_str();
    CLI::Option* matrices = command->add_option(
        "--camera-matrices", source.camera_matrices,
        "an engine's camera replacing the scene's: its view and projection matrices in a GLSL, HLSL or JSON file "
        "(README: Debugging your engine)");
    command
        ->add_option_function<std::vector<std::string>>(
            "--camera-conventions",
            [&source](const std::vector<std::string>& pairs) {
                source.camera_conventions = parse_settings(pairs, "--camera-conventions");
            },
            "the matrices' conventions, key=value,...: storage (auto | column_major | row_major), clip_depth "
            "(minus_one_to_one | zero_to_one), reversed_z (off | on), clip_y (up | down: Vulkan), looks_along "
            "(minus_z | plus_z: Direct3D)")
        ->delimiter(',')
        ->needs(matrices);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string method_help = shadowlab::method_names(" | ");
    const std::string scene_help = "scene file: JSON, glTF (.gltf, .glb) or a mesh alone";
    CLI::App app{"ShadowLab: an inspector for shadow-map parameterizations"};
    app.require_subcommand(0, 1);

    shadowlab::InspectOptions inspect;
    std::vector<std::string> set_pairs;
    CLI::App* inspect_cmd = app.add_subcommand("inspect", "print a method's steps, matrices and fallbacks for a scene");
    inspect_cmd->add_option("scene", inspect.scene_file, scene_help)->required();
    add_scene_source(inspect_cmd, inspect.scene_source);
    inspect_cmd->add_option("--method,-m", inspect.method, method_help)->capture_default_str();
    inspect_cmd->add_option("--set", set_pairs, "a method setting, key=value (repeatable)");
    inspect_cmd->add_flag("--json", inspect.json, "print one JSON object instead of text");

    shadowlab::MeasureOptions measure;
    std::vector<std::string> measure_pairs;
    std::string size = "1280x720";
    CLI::App* measure_cmd = app.add_subcommand("measure", "a method's error against the exact reference, and its cost");
    measure_cmd->add_option("scene", measure.scene_file, scene_help)->required();
    add_scene_source(measure_cmd, measure.scene_source);
    measure_cmd->add_option("--method,-m", measure.method, method_help)->capture_default_str();
    measure_cmd->add_option("--resolution,-r", measure.resolution, "shadow map resolution (texels per side)")
        ->capture_default_str();
    measure_cmd->add_option("--size", size, "camera image size WxH")->capture_default_str();
    measure_cmd->add_option("--bias", measure.bias,
                            "depth bias in world units along the light (default: slope-scaled per pixel)");
    measure_cmd->add_option("--set", measure_pairs, "a method setting, key=value (repeatable)");
    measure_cmd->add_flag("--json", measure.json, "print one JSON object");

    shadowlab::BenchOptions bench;
    std::string bench_size = "640x360";
    CLI::App* bench_cmd =
        app.add_subcommand("bench", "every method at every resolution: a CSV and a plot of error against cost");
    bench_cmd->add_option("scenes", bench.scene_files, "scene files: JSON, glTF (.gltf, .glb) or meshes alone")
        ->required();
    add_scene_source(bench_cmd, bench.scene_source);
    bench_cmd->add_option("--methods", bench.methods, "methods, comma-separated (default: all)")->delimiter(',');
    bench_cmd->add_option("--resolutions", bench.resolutions, "map resolutions, comma-separated")
        ->delimiter(',')
        ->capture_default_str();
    bench_cmd->add_option("--size", bench_size, "camera image size WxH")->capture_default_str();
    bench_cmd->add_option("--out", bench.out_dir, "output directory")->required();
    bench_cmd->add_flag("--filters", bench.filters,
                        "each filter at a few kernel sizes (the methods at the first resolution): visibility error "
                        "against lookup cost");
    bench_cmd->add_option("--scheduler", bench.scheduler,
                          "the runs as Dask tasks on this scheduler (tcp://host:8786), or local: a LocalCluster of two "
                          "worker processes; writes bench.csv (README: Corpus runs on Dask)");

    shadowlab::SweepOptions sweep;
    std::string sweep_size = "480x270";
    CLI::App* sweep_cmd = app.add_subcommand("sweep",
                                             "light from perpendicular to parallel with the view, and far/near from 10 "
                                             "to 1e7; or, with --bias, a depth bias");
    sweep_cmd->add_option("scene", sweep.scene_file, scene_help)->required();
    add_scene_source(sweep_cmd, sweep.scene_source);
    sweep_cmd->add_option("--methods", sweep.methods, "methods, comma-separated (default: all)")->delimiter(',');
    sweep_cmd->add_option("--resolution,-r", sweep.resolution, "map resolution")->capture_default_str();
    sweep_cmd->add_option("--size", sweep_size, "camera image size WxH")->capture_default_str();
    sweep_cmd->add_option("--out", sweep.out_dir, "output directory")->required();
    std::vector<std::string> sweep_pairs;
    CLI::Option* sweep_bias = sweep_cmd->add_flag(
        "--bias", sweep.bias,
        "instead: acne and peter panning against a depth bias setting, each map method at a ladder of its values");
    sweep_cmd->add_option("--bias-setting", sweep.bias_setting, "with --bias: bias_slope | bias_normal | bias_constant")
        ->capture_default_str()
        ->check(CLI::IsMember(shadowlab::kBiasSettings))
        ->needs(sweep_bias);
    sweep_cmd->add_option("--set", sweep_pairs, "with --bias: a method setting, key=value (repeatable)")
        ->needs(sweep_bias);

    shadowlab::RenderOptions render;
    std::vector<std::string> render_pairs;
    std::string render_size = "1280x720";
    CLI::App* render_cmd =
        app.add_subcommand("render", "draw one view to a PNG without showing a window (needs X: xvfb-run)");
    render_cmd->add_option("scene", render.scene_file, scene_help)->required();
    add_scene_source(render_cmd, render.scene_source);
    render_cmd->add_option("--method,-m", render.method, method_help)->capture_default_str();
    render_cmd->add_option("--view", render.view, shadowlab::view_names(" | "))->capture_default_str();
    render_cmd->add_option("--step", render.step, "the trace step to highlight (see `inspect`); default: the last");
    render_cmd->add_option("--size", render_size, "image size WxH")->capture_default_str();
    render_cmd->add_option("--resolution,-r", render.resolution, "shadow map resolution")->capture_default_str();
    render_cmd->add_option("--bias", render.bias,
                           "depth bias in world units along the light (default: slope-scaled per pixel)");
    render_cmd
        ->add_option("--aliasing", render.aliasing,
                     "the Error view's heat map: total (m) | perspective | projection (its factors)")
        ->capture_default_str();
    render_cmd
        ->add_option("--error", render.error,
                     "the Error view: verdicts (false shadow, false light, m) | signed (visibility error, "
                     "method − reference) | causes (each misclassified pixel's cause: acne, peter panning, "
                     "under-sampling, ...) | auto (signed where shadows are soft)")
        ->capture_default_str();
    render_cmd
        ->add_option("--texture", render.texture,
                     "the Shadow map view: depth | mean | deviation (the blurred moments a vsm, evsm, msm or "
                     "esm filter reads)")
        ->capture_default_str();
    render_cmd->add_option("--light", render.light,
                           "the light's direction AZ,EL in degrees: azimuth about +y from +x toward +z, elevation "
                           "above the ground (default: the scene's)");
    render_cmd->add_option("--preset", render.preset, "World, Light space and PPLS views: orbit | light | side")
        ->capture_default_str();
    render_cmd
        ->add_option("--overlay", render.overlay,
                     "Camera view of a map method: none | cascade (the map serving each surface) | texels "
                     "(the serving map's texels per pixel)")
        ->capture_default_str();
    render_cmd->add_flag("--no-scene-in-ppls{false}", render.scene_in_ppls,
                         "PPLS view: leave the scene's triangles out");
    render_cmd->add_option("--set", render_pairs, "a method setting, key=value (repeatable)");
    render_cmd->add_option("--out,-o", render.out, "PNG file to write")->required();

    shadowlab::LessonOptions lesson;
    std::vector<std::string> lesson_pairs;
    std::string lesson_size = "640x400";
    CLI::App* lesson_cmd = app.add_subcommand(
        "lesson", "a course page: every step's formula, values and pictures as HTML and PNGs (needs X: xvfb-run)");
    lesson_cmd->add_option("scene", lesson.scene_file, scene_help)->required();
    add_scene_source(lesson_cmd, lesson.scene_source);
    lesson_cmd->add_option("--method,-m", lesson.method, method_help)->capture_default_str();
    lesson_cmd->add_option("--set", lesson_pairs, "a method setting, key=value (repeatable)");
    lesson_cmd->add_option("--resolution,-r", lesson.resolution, "shadow map resolution")->capture_default_str();
    lesson_cmd->add_option("--size", lesson_size, "size of each picture WxH")->capture_default_str();
    lesson_cmd->add_flag("--row-vectors", lesson.row_vectors, "matrices as the papers print them (row vectors)");
    lesson_cmd->add_flag("--interactive", lesson.interactive,
                         "one self-contained page (index.html, opens offline) whose World, Light space and PPLS "
                         "views orbit in the browser");
    lesson_cmd->add_option("--out,-o", lesson.out, "directory to write index.html and its pictures to")->required();

    shadowlab::CompareOptions compare;
    std::vector<std::string> compare_pairs, compare_pairs_a, compare_pairs_b;
    std::string compare_size = "1280x720";
    CLI::App* compare_cmd = app.add_subcommand(
        "compare",
        "two methods, or one method with two settings, against one exact reference: the difference image, the two "
        "measures side by side and each one's lesson section (needs X: xvfb-run)");
    compare_cmd->add_option("scene", compare.scene_file, scene_help)->required();
    add_scene_source(compare_cmd, compare.scene_source);
    compare_cmd
        ->add_option("--methods", compare.methods,
                     "A,B: two methods (" + method_help +
                         "), the same one twice to "
                         "compare settings")
        ->delimiter(',')
        ->required();
    compare_cmd->add_option("--set", compare_pairs, "a setting of both, key=value (repeatable)");
    compare_cmd->add_option("--set-a", compare_pairs_a, "a setting of A alone, over --set (repeatable)");
    compare_cmd->add_option("--set-b", compare_pairs_b, "a setting of B alone, over --set (repeatable)");
    compare_cmd->add_option("--resolution,-r", compare.resolution, "shadow map resolution")->capture_default_str();
    compare_cmd->add_option("--size", compare_size, "camera image size WxH")->capture_default_str();
    compare_cmd->add_option("--bias", compare.bias,
                            "depth bias in world units along the light (default: slope-scaled per pixel)");
    compare_cmd
        ->add_option("--out,-o", compare.out,
                     "directory to write difference.png, compare.json, compare.md and lesson.html to")
        ->required();

    shadowlab::ShimmerOptions shimmer;
    std::vector<std::string> shimmer_pairs;
    std::string shimmer_size = "640x360";
    CLI::App* shimmer_cmd = app.add_subcommand(
        "shimmer", "the camera moved along a path: how often fixed points' shadow verdicts flip between frames");
    shimmer_cmd->add_option("scene", shimmer.scene_file, scene_help)->required();
    add_scene_source(shimmer_cmd, shimmer.scene_source);
    shimmer_cmd->add_option("--method,-m", shimmer.method, method_help)->capture_default_str();
    shimmer_cmd->add_option("--set", shimmer_pairs, "a method setting, key=value (repeatable)");
    shimmer_cmd->add_option("--path", shimmer.path, "translate (sideways) | rotate (on the spot) | dolly (forward)")
        ->capture_default_str();
    shimmer_cmd->add_option("--frames", shimmer.frames, "frames along the path")->capture_default_str();
    shimmer_cmd
        ->add_option("--step", shimmer.step,
                     "per frame: world units (translate, dolly) or degrees (rotate); 0: automatic "
                     "(0.5 % of the distance to the target, 0.25°)")
        ->capture_default_str();
    shimmer_cmd->add_option("--resolution,-r", shimmer.resolution, "shadow map resolution")->capture_default_str();
    shimmer_cmd
        ->add_option("--size", shimmer_size, "camera image size WxH (its visible receiver pixels are the points)")
        ->capture_default_str();
    shimmer_cmd->add_option("--out", shimmer.out_dir, "output directory")->required();

    shadowlab::InspectorOptions gui;
    gui.scene_file = default_scene();
    std::string gui_size = "1600x1000";
    CLI::App* gui_cmd =
        app.add_subcommand("gui", "open the inspector window (the default with no sub-command and an X display)");
    gui_cmd->add_option("scene", gui.scene_file, "scene (JSON) or mesh file")->capture_default_str();
    gui_cmd->add_option("--screenshot", gui.screenshot, "write the window to this PNG once drawn, then quit");
    gui_cmd->add_option("--size", gui_size, "window size WxH")->capture_default_str();
    gui_cmd
        ->add_option("--compare", gui.compare, "A,B: open in compare mode, method A beside method B (View > Compare)")
        ->delimiter(',')
        ->expected(2);

    try {
        app.parse(argc, argv);
        const bool no_subcommand = app.get_subcommands().empty();
        if (app.got_subcommand(gui_cmd) || (no_subcommand && std::getenv("DISPLAY"))) {
            parse_size(gui_size, gui.width, gui.height);
            for (const std::string& method : gui.compare) shadowlab::method_or_throw(method);
            return shadowlab::run_inspector(argc > 0 ? 1 : 0, argv, gui);
        }
        if (app.got_subcommand(render_cmd)) {
            render.settings = parse_settings(render_pairs);
            parse_size(render_size, render.width, render.height);
            shadowlab::run_render(render);
            return 0;
        }
        if (app.got_subcommand(lesson_cmd)) {
            lesson.settings = parse_settings(lesson_pairs);
            parse_size(lesson_size, lesson.width, lesson.height);
            const int pictures = shadowlab::run_lesson(lesson);
            std::cerr << "lesson: " << lesson.out << "/index.html"
                      << (lesson.interactive ? ", self-contained, with " : " and ") << pictures
                      << (lesson.interactive ? " views\n" : " pictures\n");
            return 0;
        }
        if (app.got_subcommand(compare_cmd)) {
            compare.settings = parse_settings(compare_pairs);
            compare.settings_a = parse_settings(compare_pairs_a, "--set-a");
            compare.settings_b = parse_settings(compare_pairs_b, "--set-b");
            parse_size(compare_size, compare.width, compare.height);
            shadowlab::run_compare(compare);
            std::cerr << "compare: " << compare.out << "/difference.png, compare.json, compare.md, lesson.html\n";
            return 0;
        }
        if (app.got_subcommand(shimmer_cmd)) {
            shimmer.settings = parse_settings(shimmer_pairs);
            parse_size(shimmer_size, shimmer.width, shimmer.height);
            shadowlab::run_shimmer(shimmer);
            return 0;
        }
        if (app.got_subcommand(sweep_cmd)) {
            parse_size(sweep_size, sweep.width, sweep.height);
            sweep.settings = parse_settings(sweep_pairs);
            shadowlab::run_sweep(sweep);
            return 0;
        }
        if (app.got_subcommand(bench_cmd)) {
            parse_size(bench_size, bench.width, bench.height);
            bench.filters ? shadowlab::run_filter_bench(bench) : shadowlab::run_bench(bench);
            return 0;
        }
        if (app.got_subcommand(measure_cmd)) {
            measure.settings = parse_settings(measure_pairs);
            parse_size(size, measure.width, measure.height);
            shadowlab::run_measure(measure);
            return 0;
        }
        if (app.got_subcommand(inspect_cmd)) {
            inspect.settings = parse_settings(set_pairs);
        } else {  // no sub-command and no X display: the inspection as text
            std::cerr << "shadowlab: no X display (DISPLAY unset): printing the inspection; run under xvfb-run "
                         "or on a desktop for the window\n";
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
