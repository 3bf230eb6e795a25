#include "sweep_command.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "limits.hpp"
#include "measure_command.hpp"
#include "metrics/bias_sweep.hpp"
#include "plot/bias_chart.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {
namespace {

const std::vector<double> kAnglesDeg{90, 60, 30, 10, 3, 1, 0.3, 0.1, 0.01, 1e-3, 1e-4};
const std::vector<double> kFarOverNear{10, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7};

// The light at γ from the view direction, tilted toward the ground (from above the viewer).
Scene with_light_angle(Scene scene, double gamma_deg) {
    const glm::dvec3 v = scene.camera.view_direction();
    glm::dvec3 down = glm::dvec3(0, -1, 0) - glm::dot(glm::dvec3(0, -1, 0), v) * v;
    if (glm::length(down) < 1e-9) down = glm::cross(v, glm::dvec3(1, 0, 0));
    const double g = glm::radians(gamma_deg);
    scene.light.type = LightType::directional;
    scene.light.direction = glm::normalize(std::cos(g) * v + std::sin(g) * glm::normalize(down));
    return scene;
}

Scene with_far_over_near(Scene scene, double ratio) {
    scene.camera.far = scene.camera.near * ratio;
    return scene;
}

struct SweepSeries {
    std::string quantity;  // "angle_deg" or "far_over_near"
    std::vector<double> values;
    std::vector<std::vector<Measurement>> per_method;  // [method][value]
};

ChartSpec error_against(const SweepSeries& sweep, const std::vector<const Method*>& methods, const std::string& title,
                        const std::string& x_title) {
    ChartSpec chart{title, x_title, "misclassified receiver pixels (%)   (x: a fallback or a named limit)",
                    true,  false,   900,
                    600,   {}};
    for (size_t k = 0; k < methods.size(); ++k) {
        ChartSeries series;
        series.name = methods[k]->name;
        for (size_t i = 0; i < sweep.values.size(); ++i)
            add_error_point(series, sweep.values[i], sweep.per_method[k][i]);
        chart.series.push_back(std::move(series));
    }
    return chart;
}

// The map methods of `methods`; a technique without a map has no depth bias: a note on stderr.
std::vector<const Method*> with_maps(const std::vector<const Method*>& methods) {
    std::vector<const Method*> kept;
    for (const Method* method : methods) {
        if (method->makes_maps())
            kept.push_back(method);
        else
            std::cerr << "sweep: " << method->name << " skipped: a geometric technique has no depth bias\n";
    }
    if (kept.empty()) throw std::invalid_argument("--bias: none of the methods makes a map");
    return kept;
}

void write_bias_csv(const std::vector<BiasCurve>& curves, const std::filesystem::path& file) {
    std::ofstream csv(file);
    if (!csv) throw std::runtime_error(file.string() + ": cannot write");
    csv << "method,setting,value,false_shadow,false_light,misclassified,best,fallback\n";
    for (const BiasCurve& curve : curves)
        for (size_t i = 0; i < curve.points.size(); ++i) {
            const BiasPoint& p = curve.points[i];
            csv << curve.method << ',' << curve.setting << ',' << p.value << ',' << p.false_shadow << ','
                << p.false_light << ',' << p.misclassified << ',' << (i == curve.best) << ",\"" << describe(p.fallbacks)
                << "\"\n";
        }
}

// "focused: best bias_slope 1.41× → misclassified 0.31 % (false shadow 0.1 %, false light 0.21 %)"
void print_best(const BiasCurve& curve) {
    const BiasPoint& best = curve.points[curve.best];
    std::cout << curve.method << ": best " << curve.setting << " " << bias_value_text(curve.setting, best.value)
              << " → misclassified " << 100.0 * best.misclassified << " % (false shadow " << 100.0 * best.false_shadow
              << " %, false light " << 100.0 * best.false_light << " %)\n";
}

// "Acne and peter panning against bias_normal at 1024² (bias_slope=0: bias_normal alone; other
// settings at their defaults)": the settings held beside the swept one (BiasCurve::settings).
std::string bias_chart_title(const BiasCurve& curve, int resolution) {
    std::string held;
    for (const auto& [name, value] : curve.settings) held += (held.empty() ? "" : ", ") + name + "=" + value;
    if (curve.settings.count("bias_slope") && curve.settings.at("bias_slope") == "0")
        held += ": " + curve.setting + " alone";
    return "Acne and peter panning against " + curve.setting + " at " + std::to_string(resolution) + "² (" +
           (held.empty() ? "" : held + "; ") + "other settings at their defaults)";
}

void run_bias_sweep(const SweepOptions& o) {
    const std::vector<const Method*> methods = with_maps(methods_named(o.methods));
    const MeasureContext context = prepare_with_progress(o.scene_file, o.scene_source, o.width, o.height);
    const std::vector<double> values = default_bias_values(context, o.bias_setting, o.resolution);
    std::vector<BiasCurve> curves;
    for (const Method* method : methods) {
        const auto progress = [&](const BiasPoint& p, size_t done, size_t count) {
            std::cerr << "sweep: " << method->name << " " << o.bias_setting << " = " << p.value << " [" << done << "/"
                      << count << "]\n";
        };
        curves.push_back(sweep_bias(context, *method, o.settings, o.resolution, o.bias_setting, values, progress));
    }
    std::filesystem::create_directories(o.out_dir);
    const std::filesystem::path dir(o.out_dir);
    write_bias_csv(curves, dir / "sweep_bias.csv");
    write_chart_png(bias_chart(curves, context.scene.name + ": " + bias_chart_title(curves.front(), o.resolution)),
                    (dir / "sweep_bias.png").string());
    for (const BiasCurve& curve : curves) print_best(curve);
    std::cout << "wrote " << (dir / "sweep_bias.csv").string() << " and " << (dir / "sweep_bias.png").string() << "\n";
}

}  // namespace

void run_sweep(const SweepOptions& o) {
    if (o.out_dir.empty()) throw std::invalid_argument("--out: a directory is required");
    limits::check(limits::map_resolution, "--resolution", o.resolution);
    if (o.bias) return run_bias_sweep(o);
    const std::vector<const Method*> methods = methods_named(o.methods);
    const Scene base = load_scene_source(o.scene_file, o.scene_source);
    std::filesystem::create_directories(o.out_dir);
    const std::filesystem::path dir(o.out_dir);
    std::ofstream csv(dir / "sweep.csv");
    if (!csv) throw std::runtime_error((dir / "sweep.csv").string() + ": cannot write");
    csv << "quantity,value,method,misclassified,false_shadow,false_light,m_mean,m_p95,m_perspective_max,"
           "m_perspective_mean,m_perspective_p95,fallback\n";

    auto sweep = [&](const std::string& quantity, const std::vector<double>& values, auto scene_at) {
        SweepSeries s{quantity, values, std::vector<std::vector<Measurement>>(methods.size())};
        for (size_t i = 0; i < values.size(); ++i) {
            std::cerr << "sweep: " << quantity << " = " << values[i] << " [" << i + 1 << "/" << values.size() << "]\n";
            const MeasureContext context = prepare_measurement(scene_at(values[i]), o.width, o.height);
            for (size_t k = 0; k < methods.size(); ++k) {
                const Settings settings = resolve_settings(methods[k]->name, methods[k]->settings, {});
                const Measurement m = measure(context, *methods[k], settings, o.resolution, -1.0);
                const ShadowError& e = m.error;
                csv << quantity << ',' << values[i] << ',' << m.method << ',' << e.misclassified << ','
                    << e.false_shadow << ',' << e.false_light << ',' << e.m.mean << ',' << e.m.p95 << ','
                    << e.m_perspective.max << ',' << e.m_perspective.mean << ',' << e.m_perspective.p95 << ",\""
                    << describe(m.notes()) << "\"\n";
                s.per_method[k].push_back(m);
            }
        }
        return s;
    };
    const SweepSeries angles = sweep("angle_deg", kAnglesDeg, [&](double g) { return with_light_angle(base, g); });
    const SweepSeries ratios =
        sweep("far_over_near", kFarOverNear, [&](double r) { return with_far_over_near(base, r); });
    csv.close();
    std::cout << "wrote " << (dir / "sweep.csv").string() << "\n";
    write_chart_png(error_against(angles, methods, "Error as the light turns parallel to the view",
                                  "angle γ between light and view (degrees)"),
                    (dir / "sweep_angle.png").string());
    write_chart_png(error_against(ratios, methods, "Error against far/near", "far / near"),
                    (dir / "sweep_far_near.png").string());
    std::cout << "wrote " << (dir / "sweep_angle.png").string() << " and " << (dir / "sweep_far_near.png").string()
              << "\n";
}

}  // namespace shadowlab
