#include "compare_command.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "lesson_page.hpp"
#include "limits.hpp"
#include "measure_command.hpp"
#include "views/offscreen_view.hpp"
#include "what_goes_wrong.hpp"

namespace shadowlab {
namespace {

// One side of the comparison: its method and settings, measured and diagnosed on the shared reference.
struct Configuration {
    std::string label;  // "A", "B"
    const Method* method;
    Settings settings;
    std::map<std::string, std::string> overrides;  // as given, for the inspection the pictures draw
    Measurement run;
    Diagnosis diagnosis;
};

// The method named and the settings both sides share, with this side's own over them; a bad one
// throws naming the side and the option.
Configuration configured(const std::string& label, const std::string& method_name,
                         const std::map<std::string, std::string>& shared,
                         const std::map<std::string, std::string>& own) {
    std::map<std::string, std::string> overrides = shared;
    for (const auto& [key, value] : own) overrides[key] = value;
    const std::string option = label == "A" ? "--set-a" : "--set-b";
    try {
        const Method& method = method_or_throw(method_name);
        return {.label = label,
                .method = &method,
                .settings = resolve_settings(method.name, method.settings, overrides),
                .overrides = overrides,
                .run = {},
                .diagnosis = {}};
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string(find_method(method_name) ? option + " (or --set)" : "--methods") +
                                    ", configuration " + label + ": " + e.what());
    }
}

void check(const CompareOptions& o) {
    if (o.methods.size() != 2)
        throw std::invalid_argument(
            "--methods: expected two methods A,B (the same one twice to compare settings), got " +
            std::to_string(o.methods.size()));
    if (o.out.empty()) throw std::invalid_argument("--out: a directory is required");
    limits::check(limits::map_resolution, "--resolution", o.resolution);
}

Inspection inspected(const MeasureContext& context, const Configuration& c, const CompareOptions& o) {
    return inspect_scene(context.scene, {.method = c.method->name,
                                         .settings = c.overrides,
                                         .resolution = o.resolution,
                                         .bias = o.bias,
                                         .image_width = context.reference.width,
                                         .image_height = context.reference.height});
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f %%", 100.0 * share);
    return text;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

// "filter=pcf, bias_slope=2": the settings given, or "defaults".
std::string given(const std::map<std::string, std::string>& overrides) {
    std::string text;
    for (const auto& [key, value] : overrides) text += (text.empty() ? "" : ", ") + key + "=" + value;
    return text.empty() ? "defaults" : text;
}

std::string row(const std::string& name, const std::string& a, const std::string& b) {
    return "| " + name + " | " + a + " | " + b + " |\n";
}

// The two measures side by side, then who is right where they differ.
std::string markdown_table(const Configuration& a, const Configuration& b, const VerdictComparison& c,
                           const MeasureContext& context) {
    const ShadowError &ea = a.run.error, &eb = b.run.error;
    std::string md = "# " + a.method->name + " (A) against " + b.method->name + " (B)\n\nOne exact reference, " +
                     std::to_string(context.reference.width) + "x" + std::to_string(context.reference.height) +
                     " camera image, " + std::to_string(c.receiver_pixels) + " receiver pixels.\n\n";
    md += row("measure", "A", "B") + "|---|---|---|\n";
    md += row("method", a.method->name, b.method->name);
    md += row("settings given", given(a.overrides), given(b.overrides));
    md += row("misclassified", percent(ea.misclassified), percent(eb.misclassified));
    md += row("misclassified pixels", std::to_string(c.a_wrong()), std::to_string(c.b_wrong()));
    md += row("false shadow", percent(ea.false_shadow), percent(eb.false_shadow));
    md += row("false light", percent(ea.false_light), percent(eb.false_light));
    md += row("m max / mean / p95", number(ea.m.max) + " / " + number(ea.m.mean) + " / " + number(ea.m.p95),
              number(eb.m.max) + " / " + number(eb.m.mean) + " / " + number(eb.m.p95));
    md += row("visibility RMSE", number(ea.visibility.rmse), number(eb.visibility.rmse));
    md += row("setup + raster ms", number(a.run.setup_ms + a.run.raster_ms), number(b.run.setup_ms + b.run.raster_ms));
    md += row("notes", a.run.notes().empty() ? "none" : describe(a.run.notes()),
              b.run.notes().empty() ? "none" : describe(b.run.notes()));
    md += "\n| where | pixels | share |\n|---|---|---|\n";
    for (const auto& [name, pixels] :
         {std::pair{"both right", c.both_right}, std::pair{"both wrong", c.both_wrong},
          std::pair{"only A right", c.only_a_right}, std::pair{"only B right", c.only_b_right}})
        md +=
            row(name, std::to_string(pixels), percent(double(pixels) / double(std::max<size_t>(c.receiver_pixels, 1))));
    return md + "\n![Difference](difference.png)\n";
}

Json run_json(const Configuration& c) {
    Json json = to_json(c.run);
    json["diagnosis"] = to_json(c.diagnosis);
    return json;
}

}  // namespace

Json to_json(const VerdictComparison& c) {
    return {{"receiver_pixels", c.receiver_pixels}, {"both_right", c.both_right},     {"both_wrong", c.both_wrong},
            {"only_a_right", c.only_a_right},       {"only_b_right", c.only_b_right}, {"differing", c.differing()}};
}

Json run_compare(const CompareOptions& o) {
    check(o);
    Configuration a = configured("A", o.methods[0], o.settings, o.settings_a);
    Configuration b = configured("B", o.methods[1], o.settings, o.settings_b);
    const MeasureContext context = prepare_with_progress(o.scene_file, o.scene_source, o.width, o.height);
    for (Configuration* c : {&a, &b}) {
        std::cerr << "compare: " << c->label << ": " << c->method->name << " (" << given(c->overrides) << ")...\n";
        c->run = measure(context, *c->method, c->settings, o.resolution, o.bias);
        c->diagnosis = diagnose(context, *c->method, c->settings, o.resolution, o.bias, c->run);
    }
    const VerdictComparison comparison = compare_verdicts(a.run.error, b.run.error);
    const std::filesystem::path dir(o.out);
    std::filesystem::create_directories(dir);

    const Json json = {{"image", {context.reference.width, context.reference.height}},
                       {"a", run_json(a)},
                       {"b", run_json(b)},
                       {"comparison", to_json(comparison)}};
    write_text_file(dir / "compare.json", json.dump(1) + "\n");
    write_text_file(dir / "compare.md", markdown_table(a, b, comparison, context));

    const Inspection in_a = inspected(context, a, o), in_b = inspected(context, b, o);
    ViewOptions difference{.width = context.reference.width, .height = context.reference.height};
    difference.compared = std::make_shared<const Inspection>(in_b);
    write_png(
        render_view(in_a, view_or_throw("difference"), difference, context.reference.width, context.reference.height),
        (dir / "difference.png").string());
    std::string lesson = "<h1>" + a.method->name + " (A) against " + b.method->name +
                         " (B)</h1>\n<figure><img src=\"difference.png\" alt=\"Difference\"><figcaption>Where the "
                         "verdicts differ, who is right: orange A, blue B</figcaption></figure>\n";
    const PictureSource beside_page = [&](const RgbImage& image, const std::string& name) {
        write_png(image, (dir / name).string());
        return name;
    };
    for (const auto& [c, in] : {std::pair{&a, &in_a}, std::pair{&b, &in_b}})
        lesson += what_goes_wrong_section(
            *in, context, c->run, c->diagnosis,
            {.id = "what-goes-wrong-" + c->label,
             .heading = c->label + ": " + c->method->name + " (" + given(c->overrides) + "): what goes wrong",
             .picture = "error-causes-" + c->label + ".png",
             .width = context.reference.width,
             .height = context.reference.height},
            beside_page);
    write_text_file(dir / "lesson.html",
                    lesson_page("compare: " + a.method->name + " against " + b.method->name, lesson));
    return json;
}

}  // namespace shadowlab
