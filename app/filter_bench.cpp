#include "filter_bench.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>

#include "limits.hpp"
#include "measure_command.hpp"

namespace shadowlab {
namespace {

using Overrides = std::map<std::string, std::string>;

// One line of the plot: a filter family and the kernel sizes it is measured at.
struct FilterFamily {
    std::string name;
    Overrides settings;
    std::vector<int> kernel_sizes;
};

const std::vector<FilterFamily>& filter_families() {
    static const std::vector<FilterFamily> families{
        {"hard", {{"filter", "hard"}}, {1}},
        {"pcf box", {{"filter", "pcf"}, {"pcf_kernel", "box"}}, {2, 3, 5}},
        {"pcf tent", {{"filter", "pcf"}, {"pcf_kernel", "tent"}}, {3, 5}},
        {"pcf poisson", {{"filter", "pcf"}, {"pcf_kernel", "poisson"}, {"filter_radius", "1.5"}}, {3, 4, 6}},
        {"pcss", {{"filter", "pcss"}}, {3, 4, 6}},
        {"vsm", {{"filter", "vsm"}}, {3, 5}},
        {"vsm, bleeding reduced 0.3", {{"filter", "vsm"}, {"bleed_reduction", "0.3"}}, {3, 5}},
        {"evsm", {{"filter", "evsm"}}, {3, 5}},
        {"msm", {{"filter", "msm"}}, {3, 5}},
        {"msm, 16 bits", {{"filter", "msm"}, {"msm_quantization", "unorm16"}}, {3, 5}},
        {"esm", {{"filter", "esm"}}, {3, 5}},
    };
    return families;
}

double cost_ms(const Measurement& m) { return m.prefilter_ms + m.lookup_ms; }

// What sets a point's cost: a prefiltered map's blur, or the taps per pixel (PCSS: the mean of its
// two passes, the filter skipped where the search finds no blocker).
std::string point_label(const Measurement& m, int kernel_size) {
    if (m.lookup.filter.reads_moments()) return std::to_string(kernel_size) + "² blur";
    if (!m.lookup.filter.soft()) return "";
    return std::to_string(int(m.taps_per_pixel + 0.5)) + " taps";
}

}  // namespace

void run_filter_bench(const BenchOptions& o) {
    if (o.out_dir.empty()) throw std::invalid_argument("--out: a directory is required");
    if (o.scene_files.size() != 1) throw std::invalid_argument("bench --filters: one scene");
    const int resolution = o.resolutions.front();
    limits::check(limits::map_resolution, "--resolutions", resolution);
    std::vector<const Method*> methods =
        methods_named(o.methods.empty() ? std::vector<std::string>{"focused"} : o.methods);
    std::filesystem::create_directories(o.out_dir);
    const std::filesystem::path dir(o.out_dir);
    std::ofstream csv(dir / "bench_filters.csv");
    if (!csv) throw std::runtime_error((dir / "bench_filters.csv").string() + ": cannot write");
    csv << "method,filter,kernel_size,taps_per_pixel,visibility_rmse,visibility_mae,reference_noise,"
           "penumbra_width_ratio,light_bleeding,misclassified,prefilter_ms,lookup_ms,fallback\n";
    const MeasureContext context = prepare_with_progress(o.scene_files.front(), o.scene_source, o.width, o.height);
    const std::string reference =
        context.reference.light_samples > 0 ? "soft reference" : "hard reference: the light has no size";
    ChartSpec chart{
        .title = "Filters: visibility error against cost (" + std::to_string(resolution) + "², " + reference + ")",
        .x_title = "lookups per frame: moments' blur + every receiver pixel (ms, both cores)",
        .y_title = "visibility RMSE against the reference",
        .log_x = true,
        .legend = ChartSpec::LegendCorner::bottom_left};
    for (const Method* method : methods) {
        if (!method->makes_maps()) {
            std::cerr << "bench --filters: " << method->name << " has no map to filter: skipped\n";
            continue;
        }
        for (const FilterFamily& family : filter_families()) {
            ChartSeries series{.name = methods.size() > 1 ? method->name + " " + family.name : family.name};
            for (int n : family.kernel_sizes) {
                Overrides overrides = family.settings;
                overrides["kernel_size"] = std::to_string(n);
                std::cerr << "bench --filters: " << method->name << " " << family.name << " " << n << "\n";
                const Measurement m = measure(
                    context, *method, resolve_settings(method->name, method->settings, overrides), resolution, -1.0);
                const VisibilityError& v = m.error.visibility;
                csv << m.method << ",\"" << family.name << "\"," << n << ',' << m.taps_per_pixel << ',' << v.rmse << ','
                    << v.mae << ',' << v.reference_noise << ','
                    << (v.penumbra_width_ratio ? std::to_string(*v.penumbra_width_ratio) : std::string()) << ','
                    << v.light_bleeding << ',' << m.error.misclassified << ',' << m.prefilter_ms << ',' << m.lookup_ms
                    << ",\"" << describe(m.notes()) << "\"\n";
                series.x.push_back(cost_ms(m));
                series.y.push_back(v.rmse);
                series.marked.push_back(!m.notes().empty());
                series.labels.push_back(point_label(m, n));
            }
            chart.series.push_back(std::move(series));
        }
    }
    csv.close();
    std::cout << "wrote " << (dir / "bench_filters.csv").string() << "\n";
    write_chart_png(chart, (dir / "bench_filters.png").string());
    std::cout << "wrote " << (dir / "bench_filters.png").string() << "\n";
}

}  // namespace shadowlab
