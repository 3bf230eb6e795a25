#include "bench_command.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <unistd.h>

#include "limits.hpp"
#include "measure_command.hpp"

namespace shadowlab {
namespace {

std::string csv_field(const std::string& text) {
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

void write_csv_row(std::ofstream& csv, const std::string& scene, const Measurement& m) {
    const ShadowError& e = m.error;
    csv << csv_field(scene) << ',' << m.method << ',' << m.resolution << ',' << e.misclassified << ',' << e.false_shadow
        << ',' << e.false_light << ',' << e.m.max << ',' << e.m.mean << ',' << e.m.p95 << ',' << e.m_perspective.max
        << ',' << e.m_perspective.mean << ',' << e.m_perspective.p95 << ',';
    if (m.storage)
        csv << m.storage->needed << ',' << m.storage->lower_bound << ',' << m.storage->efficiency;
    else
        csv << ",,";
    csv << ',' << m.setup_ms << ',' << m.raster_ms << ',' << m.setup_ms + m.raster_ms << ','
        << csv_field(describe(m.notes())) << ',';
    if (m.geometry)
        csv << m.geometry->polygons << ',' << m.geometry->fill_mean << ',' << m.geometry->fill_max;
    else
        csv << ",,";
    csv << '\n';
}

using Runs = std::vector<std::pair<std::string, std::vector<Measurement>>>;

// Which of a method's measurements a chart shows: one per resolution, or its largest resolution's.
enum class Resolutions { every, largest };

// One line per method (and scene), one point per resolution (or the largest's alone): `value` of each
// measurement against its total cost (setup + rasterization); a measurement without a value
// (nullopt) is left out, and so is a line left with no point. A cross marks a fallback or a named
// limit.
template <class Value>
ChartSpec against_cost(ChartSpec chart, const Runs& runs, Value&& value, Resolutions shown = Resolutions::every) {
    for (const auto& [name, measurements] : runs) {
        ChartSeries series;
        series.name = name;
        for (const Measurement& m : measurements)
            if (const std::optional<double> y = value(m);
                y && (shown == Resolutions::every || &m == &measurements.back())) {
                series.x.push_back(m.setup_ms + m.raster_ms);
                series.y.push_back(*y);
                series.marked.push_back(!m.notes().empty());
                series.labels.push_back(m.geometry ? std::string("exact") : std::to_string(m.resolution));
            }
        if (!series.x.empty()) chart.series.push_back(std::move(series));
    }
    return chart;
}

// The misclassified share of every method and technique.
ChartSpec error_against_cost(const Runs& runs) {
    return against_cost({"Speed-accuracy trade: error against cost",
                         "cost per frame: setup + rasterization (ms)",
                         "misclassified receiver pixels (%)",
                         true,
                         false,
                         900,
                         600,
                         {}},
                        runs, [](const Measurement& m) { return std::optional(100.0 * m.error.misclassified); });
}

// Max perspective m of the map methods. The perspective factor, not m: m's max is set by faces
// edge-on to the light, which no parameterization can help. Techniques have no texels and no line.
ChartSpec aliasing_against_cost(const Runs& runs) {
    return against_cost({"Perspective aliasing against cost",
                         "cost per frame: setup + rasterization (ms)",
                         "max perspective m (texel width in pixels)",
                         true,
                         true,
                         900,
                         600,
                         {}},
                        runs, [](const Measurement& m) {
                            return m.geometry ? std::nullopt : std::optional(m.error.m_perspective.max);
                        });
}

// The storage efficiency of the map methods (metrics/storage_bound.hpp: the view's lower bound on
// the texels for a max perspective m of 1 over the texels the method needs for it), one point per
// method at the largest resolution: the efficiency does not follow the resolution (both counts are
// the texels at which m reaches 1), its cost does.
ChartSpec efficiency_against_cost(const Runs& runs) {
    return against_cost(
        {"Storage efficiency against cost (largest resolution)",
         "cost per frame: setup + rasterization (ms)",
         "storage efficiency (lower bound / texels needed)",
         true,
         true,
         900,
         600,
         {},
         ChartSpec::LegendCorner::bottom_right},
        runs,
        [](const Measurement& m) {
            return m.storage && m.storage->efficiency > 0.0 ? std::optional(m.storage->efficiency) : std::nullopt;
        },
        Resolutions::largest);
}

// The runs of `o` as Dask tasks: this process becomes `python3 -m shadowlab.bench` (one
// implementation of the corpus run: python/shadowlab/corpus.py), the package imported from the build tree.
[[noreturn]] void run_bench_on_dask(const BenchOptions& o) {
#ifdef SHADOWLAB_PYTHON_PACKAGE_DIR
    if (!o.scene_source.camera_matrices.empty() || o.scene_source.choice.camera || o.scene_source.choice.light)
        throw std::invalid_argument("--scheduler: each scene file's first camera and light only");
    auto joined = [](const std::vector<std::string>& items) {
        std::string out;
        for (const std::string& item : items) {
            if (!out.empty()) out += ',';
            out += item;
        }
        return out;
    };
    std::vector<std::string> resolutions;
    for (int r : o.resolutions) resolutions.push_back(std::to_string(r));
    std::vector<std::string> args{SHADOWLAB_PYTHON_EXECUTABLE, "-m", "shadowlab.bench"};
    args.insert(args.end(), o.scene_files.begin(), o.scene_files.end());
    args.insert(args.end(), {"--methods", joined(o.methods), "--resolutions", joined(resolutions), "--size",
                             std::to_string(o.width) + "x" + std::to_string(o.height), "--scheduler", o.scheduler,
                             "--out", o.out_dir});
    const char* path = std::getenv("PYTHONPATH");
    setenv("PYTHONPATH", (SHADOWLAB_PYTHON_PACKAGE_DIR + std::string(path ? ":" + std::string(path) : "")).c_str(), 1);
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    throw std::runtime_error("--scheduler: cannot run " + args[0] + ": " + std::strerror(errno));
#else
    throw std::invalid_argument(
        "--scheduler: this build has no Python module (configured with -DSHADOWLAB_PYTHON=OFF)");
#endif
}

}  // namespace

void run_bench(const BenchOptions& o) {
    if (o.out_dir.empty()) throw std::invalid_argument("--out: a directory is required");
    if (!o.scheduler.empty()) run_bench_on_dask(o);
    const std::vector<const Method*> methods = methods_named(o.methods);
    for (int r : o.resolutions) limits::check(limits::map_resolution, "--resolutions", r);
    std::filesystem::create_directories(o.out_dir);
    const std::string csv_path = (std::filesystem::path(o.out_dir) / "bench.csv").string();
    std::ofstream csv(csv_path);
    if (!csv) throw std::runtime_error(csv_path + ": cannot write");
    csv << "scene,method,resolution,misclassified,false_shadow,false_light,m_max,m_mean,m_p95,m_perspective_max,"
           "m_perspective_mean,m_perspective_p95,storage_needed,storage_lower_bound,storage_efficiency,setup_ms,raster_"
           "ms,total_ms,fallback,polygons,fill_mean,fill_max\n";

    Runs runs;
    // A technique has no map: it is measured once per scene, whatever the resolutions.
    auto resolutions_of = [&](const Method* m) { return m->makes_maps() ? o.resolutions : std::vector<int>{0}; };
    size_t total = 0, done = 0;
    for (const Method* m : methods) total += o.scene_files.size() * resolutions_of(m).size();
    for (const std::string& scene_file : o.scene_files) {
        const MeasureContext context = prepare_with_progress(scene_file, o.scene_source, o.width, o.height);
        const std::string scene_name = std::filesystem::path(scene_file).stem().string();
        for (const Method* method : methods) {
            const Settings settings = resolve_settings(method->name, method->settings, {});
            auto& series =
                runs.emplace_back(o.scene_files.size() > 1 ? method->name + " (" + scene_name + ")" : method->name,
                                  std::vector<Measurement>{});
            for (int resolution : resolutions_of(method)) {
                std::cerr << "bench: [" << ++done << "/" << total << "] " << scene_name << " " << method->name;
                if (method->makes_maps()) std::cerr << " " << resolution << "^2";
                std::cerr << "\n";
                series.second.push_back(measure(context, *method, settings, resolution, -1.0));
                write_csv_row(csv, scene_name, series.second.back());
            }
        }
    }
    csv.close();
    std::cout << "wrote " << csv_path << "\n";
    const std::string png_path = (std::filesystem::path(o.out_dir) / "bench.png").string();
    write_chart_png(error_against_cost(runs), png_path);
    std::cout << "wrote " << png_path << "\n";
    const std::string aliasing_path = (std::filesystem::path(o.out_dir) / "bench_aliasing.png").string();
    write_chart_png(aliasing_against_cost(runs), aliasing_path);
    std::cout << "wrote " << aliasing_path << "\n";
    const std::string storage_path = (std::filesystem::path(o.out_dir) / "bench_storage.png").string();
    write_chart_png(efficiency_against_cost(runs), storage_path);
    std::cout << "wrote " << storage_path << "\n";
}

}  // namespace shadowlab
