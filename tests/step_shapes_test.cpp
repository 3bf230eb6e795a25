// Every step of every registered method draws its idea: at least one shape, each finite and not
// degenerate, and the figures that carry a number agree with the value the step records (LiSPSM's γ
// and n, XPSM's projection intervals and focus region, TSM's 80% line, the unit cube [0,1]³).
#include <gtest/gtest.h>

#include <variant>

#include "methods/shadow_inputs.hpp"
#include "reference/exact_shadows.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

struct Case {
    std::string name;
    Scene scene;
};

Scene shipped(const std::string& name) { return load_scene(source_path("data/scenes/" + name + ".json")); }

// The shipped scenes the issue names, and configurations that send the warps to their fallbacks.
std::vector<Case> cases() {
    Scene along_view = shipped("default");  // light exactly along the view: γ = 0, the miner's lamp
    along_view.light.direction = along_view.camera.view_direction();
    Scene nothing_visible = shipped("default");  // looking up, away from the scene: an empty body
    nothing_visible.camera.position = {0, 500, 0};
    nothing_visible.camera.target = {0, 600, 0};
    nothing_visible.camera.up = {0, 0, 1};
    return {{"box_on_plane", shipped("box_on_plane")},
            {"default", shipped("default")},
            {"light_parallel_behind", shipped("light_parallel_behind")},
            {"point", shipped("point")},
            {"spot", shipped("spot")},
            {"light_along_view", along_view},
            {"nothing_visible", nothing_visible}};
}

Trace trace_of(const Method& method, const Scene& scene) {
    Trace trace;
    const Settings settings = resolve_settings(method.name, method.settings, {});
    if (method.makes_maps()) {
        method.compute_maps(gather_inputs(scene), settings, &trace);
    } else {
        const WorldTriangles triangles = tessellate(scene);
        method.compute_geometry(scene, triangles, exact_reference(scene, triangles, 64, 36), settings, &trace);
    }
    return trace;
}

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
bool finite(const glm::dvec4& p) { return finite(glm::dvec3(p)) && std::isfinite(p.w); }

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// Empty when the shape can be drawn; else what is wrong with it.
std::string flaw(const TraceGeometry& geometry) {
    return std::visit(
        Overloaded{
            [](const PointSet& s) -> std::string {
                if (s.points.empty()) return "no point";
                for (const glm::dvec3& p : s.points)
                    if (!finite(p)) return "a point is not finite";
                return "";
            },
            [](const Aabb& b) -> std::string {
                return b.empty() ? "empty box" : !finite(b.min) || !finite(b.max) ? "box not finite" : "";
            },
            [](const ConvexPolyhedron& p) -> std::string {
                if (p.empty()) return "empty polyhedron";
                for (const glm::dvec3& v : p.vertices)
                    if (!finite(v)) return "a vertex is not finite";
                return "";
            },
            [](const Frustum& f) -> std::string {
                for (const glm::dvec3& c : f.corners)
                    if (!finite(c)) return "a corner is not finite";
                for (const Plane& p : f.planes)
                    if (!finite(p.normal) || !std::isfinite(p.offset)) return "a plane is not finite";
                return glm::distance(f.corners[0], f.corners[6]) > 0.0 ? "" : "a frustum of one point";
            },
            [](const SegmentSet& s) -> std::string {
                if (s.segments.empty()) return "no segment";
                for (const auto& [a, b] : s.segments)
                    if (!finite(a) || !finite(b) || !(glm::distance(a, b) > 0.0)) return "a segment is degenerate";
                return "";
            },
            [](const PolygonSet& s) -> std::string {
                if (s.polygons.empty()) return "no polygon";
                for (const std::vector<int>& loop : s.polygons)
                    if (loop.size() < 3) return "a polygon of fewer than 3 vertices";
                for (const glm::dvec4& v : s.vertices)
                    if (!finite(v) || v == glm::dvec4(0.0)) return "a vertex is not a point";
                return "";
            },
            [](const Arrow& a) -> std::string {
                return finite(a.from) && finite(a.to) && glm::distance(a.from, a.to) > 0.0 ? "" : "a degenerate arrow";
            },
            [](const AngleArc& a) -> std::string {
                return finite(a.centre) && finite(a.from) && finite(a.to) && glm::length(a.from) > 0.0 &&
                               glm::length(a.to) > 0.0 && a.radius > 0.0
                           ? ""
                           : "a degenerate arc";
            },
            [](const Label& l) -> std::string {
                return l.text.empty() ? "an empty label" : finite(l.at) ? "" : "a label at no finite point";
            },
        },
        geometry);
}

const NamedGeometry* shape(const Step& step, const std::string& name) {
    for (const NamedGeometry& g : step.geometry)
        if (g.name == name) return &g;
    return nullptr;
}

template <class T>
T value(const Step& step, const std::string& name) {
    for (const NamedValue& v : step.values)
        if (v.name == name) return std::get<T>(v.value);
    throw std::runtime_error("no value " + name + " in step " + step.id);
}

// A step's own shape of that name and kind; fails the test when it is missing.
template <class T>
const T& drawn(const Trace& trace, const std::string& step_id, const std::string& name) {
    const Step* step = trace.find(step_id);
    if (!step) throw std::runtime_error("no step " + step_id);
    const NamedGeometry* g = shape(*step, name);
    if (!g) throw std::runtime_error("step " + step_id + " draws no " + name);
    return std::get<T>(g->geometry);
}

Trace trace_of(const std::string& method, const std::string& scene) {
    return trace_of(*find_method(method), shipped(scene));
}

}  // namespace

TEST(StepShapes, EveryStepOfEveryMethodDrawsFiniteShapes) {
    for (const Case& c : cases())
        for (const Method& method : all_methods()) {
            const Trace trace = trace_of(method, c.scene);
            for (const Step& step : trace.steps()) {
                const std::string where = method.name + " on " + c.name + ", step " + step.id;
                EXPECT_FALSE(step.geometry.empty()) << where << " draws nothing";
                for (const NamedGeometry& g : step.geometry) EXPECT_EQ(flaw(g.geometry), "") << where << ": " << g.name;
                // The papers' words, not ours: no "seed" in what the user reads.
                std::string text = step.title + " " + step.explanation;
                for (const NamedGeometry& g : step.geometry)
                    if (const Label* l = std::get_if<Label>(&g.geometry)) text += " " + l->text;
                EXPECT_EQ(text.find("seed"), std::string::npos) << where << ": " << text;
            }
        }
}

TEST(StepShapes, EveryUnitCubeLabelledSoIsExactlyTheUnitCube) {
    size_t labelled = 0, map_methods = 0;
    for (const Method& method : all_methods()) {
        map_methods += method.makes_maps();
        const Trace trace = trace_of(method, shipped("default"));
        for (const Step& step : trace.steps())
            for (const NamedGeometry& g : step.geometry) {
                const Label* label = std::get_if<Label>(&g.geometry);
                if (!label || label->text != "[0,1]³") continue;
                ++labelled;
                bool cube = false;
                for (const NamedGeometry& h : step.geometry)
                    if (const Aabb* box = std::get_if<Aabb>(&h.geometry))
                        cube |= h.role == Role::map && box->min == glm::dvec3(0.0) && box->max == glm::dvec3(1.0);
                EXPECT_TRUE(cube) << method.name << ", step " << step.id;
            }
    }
    EXPECT_GE(labelled, map_methods) << "every map method's unit-cube step labels it";
}

TEST(StepShapes, LispsmGammaArcAndNDimensionCarryTheirValues) {
    for (const char* scene : {"default", "box_on_plane"}) {
        const Trace trace = trace_of("lispsm", scene);
        const AngleArc& arc = drawn<AngleArc>(trace, "gamma", "γ");
        const double arc_deg = glm::degrees(std::acos(glm::dot(glm::normalize(arc.from), glm::normalize(arc.to))));
        EXPECT_NEAR(arc_deg, value<double>(*trace.find("gamma"), "gamma_deg"), 1e-9) << scene;
        EXPECT_NEAR(std::sin(glm::radians(arc_deg)), value<double>(*trace.find("gamma"), "sin_gamma"), 1e-9) << scene;
        const SegmentSet& n = drawn<SegmentSet>(trace, "n-opt", "n");
        const double drawn_n = glm::distance(n.segments.at(0).first, n.segments.at(0).second);
        EXPECT_NEAR(drawn_n, value<double>(*trace.find("n-opt"), "n"), 1e-9 * drawn_n) << scene;
        // The dimension ends at C, the warp frustum's centre.
        EXPECT_LT(glm::distance(n.segments[0].first, value<glm::dvec3>(*trace.find("warp-frustum"), "C")),
                  1e-9 * drawn_n);
    }
}

TEST(StepShapes, XpsmIntervalsAndFocusRegionAreTheStepsValues) {
    for (const char* scene : {"default", "box_on_plane"}) {
        const Trace trace = trace_of("xpsm", scene);
        const glm::dvec2 unit_p = value<glm::dvec2>(*trace.find("xpsm-3"), "unitP");
        const Step& step4 = *trace.find("xpsm-4");
        auto start_along_unit_p = [&](const char* name) {
            return glm::dot(glm::dvec2(drawn<SegmentSet>(trace, "xpsm-4", name).segments.at(0).first), unit_p);
        };
        EXPECT_NEAR(start_along_unit_p("casters' interval"), value<double>(step4, "minCastersProj"), 1e-9) << scene;
        EXPECT_NEAR(start_along_unit_p("receivers' interval"), value<double>(step4, "minReceiversProj"), 1e-9) << scene;
        EXPECT_EQ(shape(step4, "casters' interval")->role, Role::casters);
        EXPECT_EQ(shape(step4, "receivers' interval")->role, Role::receivers);

        const Step& step13 = *trace.find("xpsm-13");
        const NamedGeometry& region = *shape(step13, "FocusRegion");
        EXPECT_EQ(region.role, Role::focus);
        const PolygonSet& rectangle = std::get<PolygonSet>(region.geometry);
        ASSERT_EQ(rectangle.vertices.size(), 4u);
        EXPECT_EQ(glm::dvec2(rectangle.vertices[0]), value<glm::dvec2>(step13, "MinPoint")) << scene;
        EXPECT_EQ(glm::dvec2(rectangle.vertices[2]), value<glm::dvec2>(step13, "MaxPoint")) << scene;
    }
}

TEST(StepShapes, TsmFocusEndLandsOnTheEightyPercentLine) {
    const Trace trace = trace_of("tsm", "default");
    const PointSet& p_l = drawn<PointSet>(trace, "tsm-trapezoid-to-square", "p_L");
    EXPECT_NEAR(p_l.points.at(0).y, 0.8, 1e-9);
    // The trapezoid's corners land on the unit square's.
    const PolygonSet& square = drawn<PolygonSet>(trace, "tsm-trapezoid-to-square", "trapezoid on the square");
    for (const glm::dvec4& corner : square.vertices) {
        EXPECT_NEAR(std::min(std::abs(corner.x), std::abs(corner.x - 1.0)), 0.0, 1e-9);
        EXPECT_NEAR(std::min(std::abs(corner.y), std::abs(corner.y - 1.0)), 0.0, 1e-9);
    }
}
