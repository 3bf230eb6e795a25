// Trapezoidal Shadow Maps (Martin and Tan 2004). Seen from the light, the eye frustum is bounded by
// a trapezoid whose top line lies on the viewer's side; the projective map N_T taking that trapezoid
// onto the unit square gives the near part of the view most of the map. The 80% rule sets how much:
// the trapezoid's projection centre q is placed so that the focus region ends on the map's 80% line.
// For our directional light the light's post-perspective space is light space with an orthographic
// fit, and the eye frustum is focused to the intersection body B.
#include "methods/tsm.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "math/matrix.hpp"
#include "methods/light_fit.hpp"
#include "methods/map_fit.hpp"
#include "methods/focused.hpp"
#include "methods/step_figures.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {
namespace {

// TSM: the 80% line, ξ = -0.6 on the paper's axis from +1 (top line) to -1 (base line).
constexpr double kXi = -0.6;
// A centre line shorter than this fraction of the projected points' extent has no direction worth
// warping along (about XPSM's miner's lamp, |V.xy| < 0.1, for a 60° view).
constexpr double kDegenerateCentreLine = 0.05;
// A projection centre this many times λ before the top line is no warp at all.
constexpr double kNoWarp = 1e6;

double cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// A polygon through the points, in order, as homogeneous vertices (w = 1).
std::vector<glm::dvec4> polygon_of(const std::vector<glm::dvec3>& points) {
    std::vector<glm::dvec4> out;
    for (const glm::dvec3& p : points) out.emplace_back(p, 1.0);
    return out;
}

// Light-space xy points, put in the plane z = 0 for the trace.
std::vector<glm::dvec3> in_xy_plane(const std::vector<glm::dvec2>& points) {
    std::vector<glm::dvec3> out;
    for (const glm::dvec2& p : points) out.emplace_back(p, 0.0);
    return out;
}

struct LightView {
    glm::dmat4 light_from_world;
    std::vector<glm::dvec3> body;    // B in light space
    std::vector<glm::dvec2> points;  // B projected to the light-space xy plane
};

// TSM: the eye frustum in the light's post-perspective space, projected to its xy plane.
LightView light_view(const ShadowInputs& in, const IntersectionBody& body, Trace* trace) {
    LightView ls;
    ls.light_from_world =
        light_basis(in.light.direction, in.camera.view_direction(), in.camera.position).light_from_world;
    ls.body = transformed(body.body.vertices, ls.light_from_world);
    for (const glm::dvec3& p : ls.body) ls.points.emplace_back(p);
    record(trace, [&](Trace& t) {
        const glm::dvec3 ls_view = glm::dmat3(ls.light_from_world) * in.camera.view_direction();
        Step& step =
            t.add("tsm-light-space", "Light's post-perspective space",
                  "directional light: light space with an orthographic fit (z along the light, y the view made "
                  "perpendicular to it, origin at the eye); where the paper projects the eye frustum's 8 corners, we "
                  "project the vertices of the eye frustum focused to the body B",
                  Space::light)
                .value("world_to_light", ls.light_from_world)
                .value("eye_xy", glm::dvec2(0.0))
                .value("view_xy", glm::dvec2(ls_view))
                .shape("B", PointSet{ls.body}, Role::focus)
                .shape("B projected", PointSet{in_xy_plane(ls.points)})
                .shape("eye", PointSet{{glm::dvec3(0.0)}}, Role::view)
                .shape("eye label", Label{glm::dvec3(0.0), "eye"}, Role::view);
        draw_arrow(step, "V", glm::dvec3(0.0), ls_view, glm::length(glm::dvec2(bounds_of(ls.body).extent())) / 4,
                   Role::view);
        t.set_frame(Space::light, ls.light_from_world);
    });
    return ls;
}

// The centre line l in light-space xy; positions along it are measured from the near centre.
struct CentreLine {
    glm::dvec2 near_centre, far_centre, axis;  // axis: unit, from near toward far
    double length, extent;                     // of l, and of the projected points
    bool degenerate() const { return !(length > kDegenerateCentreLine * extent); }
    double along(const glm::dvec2& p) const { return glm::dot(p - near_centre, axis); }
};

// TSM: the centre line, from the near plane's centre to the far plane's centre, for the eye frustum
// focused to what the camera sees of the receivers (its near and far planes moved to touch them:
// seen_receiver_depths), so that the 80% rule's focus region starts where the receivers do.
CentreLine centre_line(const ShadowInputs& in, const IntersectionBody& body, const LightView& ls, Trace* trace) {
    const Camera& camera = in.camera;
    const glm::dvec3 view_dir = camera.view_direction();
    const DepthRange seen = seen_receiver_depths(in, body);
    const double near = seen.near, far = seen.far;
    CentreLine l;
    l.near_centre = glm::dvec2(transform_point(ls.light_from_world, camera.position + near * view_dir));
    l.far_centre = glm::dvec2(transform_point(ls.light_from_world, camera.position + far * view_dir));
    l.length = glm::length(l.far_centre - l.near_centre);
    l.axis = l.length > 0.0 ? (l.far_centre - l.near_centre) / l.length : glm::dvec2(0.0);
    l.extent = glm::length(glm::dvec2(bounds_of(ls.body).extent()));
    record(trace, [&](Trace& t) {
        Step& step =
            t.add("tsm-centre-line", "Centre line l",
                  "from the near plane's centre to the far plane's centre, projected; near and far moved to touch the "
                  "receivers seen; "
                  "shorter than 5% of the points' extent: the light is parallel to the view",
                  Space::light)
                .value("near", near)
                .value("far", far)
                .value("near_centre", l.near_centre)
                .value("far_centre", l.far_centre)
                .value("length", l.length)
                .value("points_extent", l.extent)
                .value("direction", l.axis)
                .shape("centres", PointSet{in_xy_plane({l.near_centre, l.far_centre})})
                .shape("near centre label", Label{{l.near_centre, 0.0}, "near centre"})
                .shape("far centre label", Label{{l.far_centre, 0.0}, "far centre"});
        if (l.length > 0.0) step.shape("l", SegmentSet{{{{l.near_centre, 0.0}, {l.far_centre, 0.0}}}});
    });
    return l;
}

// TSM: the convex hull of the projected points (Andrew's monotone chain), counter-clockwise.
std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> points, Trace* trace) {
    std::sort(points.begin(), points.end(),
              [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<glm::dvec2> hull;
    auto turns_left = [&](const glm::dvec2& p) {
        const size_t n = hull.size();
        return cross(hull[n - 1] - hull[n - 2], p - hull[n - 2]) > 0.0;
    };
    for (const glm::dvec2& p : points) {  // lower chain
        while (hull.size() >= 2 && !turns_left(p)) hull.pop_back();
        hull.push_back(p);
    }
    const size_t lower = hull.size() + 1;
    for (auto p = points.rbegin() + 1; p != points.rend(); ++p) {  // upper chain
        while (hull.size() >= lower && !turns_left(*p)) hull.pop_back();
        hull.push_back(*p);
    }
    hull.pop_back();  // the first point, reached again
    record(trace, [&](Trace& t) {
        t.add("tsm-hull", "Convex hull", "2D convex hull of the projected points", Space::light)
            .value("vertices", double(hull.size()))
            .shape("hull", PolygonSet{}.add(polygon_of(in_xy_plane(hull))));
    });
    return hull;
}

// Positions along l of the top line l_t and the base line l_b.
struct TopBase {
    double top, base;
    double lambda() const { return base - top; }
};

// TSM: l_t and l_b, perpendicular to l, touching the hull on the near and on the far side.
TopBase top_and_base(const std::vector<glm::dvec2>& hull, const CentreLine& l, Trace* trace) {
    TopBase lines{INFINITY, -INFINITY};
    for (const glm::dvec2& p : hull) {
        lines.top = std::min(lines.top, l.along(p));
        lines.base = std::max(lines.base, l.along(p));
    }
    record(trace, [&](Trace& t) {
        const glm::dvec2 across{-l.axis.y, l.axis.x};
        double left = -INFINITY, right = INFINITY;
        for (const glm::dvec2& p : hull) {
            left = std::max(left, glm::dot(p - l.near_centre, across));
            right = std::min(right, glm::dot(p - l.near_centre, across));
        }
        auto line = [&](double at) {
            const glm::dvec2 o = l.near_centre + at * l.axis;
            return SegmentSet{{{{o + right * across, 0.0}, {o + left * across, 0.0}}}};
        };
        auto middle = [&](double at) { return glm::dvec3(l.near_centre + at * l.axis, 0.0); };
        t.add("tsm-top-base-lines", "Top line l_t and base line l_b",
              "perpendicular to l, touching the hull on the near and far side; λ is their distance", Space::light)
            .value("top", lines.top)
            .value("base", lines.base)
            .value("lambda", lines.lambda())
            .shape("l_t", line(lines.top))
            .shape("l_t label", Label{middle(lines.top), "l_t"})
            .shape("l_b", line(lines.base))
            .shape("l_b label", Label{middle(lines.base), "l_b"})
            .shape("λ", SegmentSet{{{middle(lines.top), middle(lines.base)}}})
            .shape("λ label", Label{middle(0.5 * (lines.top + lines.base)), "λ = " + label_number(lines.lambda())});
    });
    return lines;
}

struct Focus {
    glm::dvec2 p_l, q;
    double delta_prime, eta;
};

// TSM: the 80% rule. The focus region ends at p_L on l, δ' beyond l_t; q lies η before l_t on l,
// η = (λδ' + λδ'ξ) / (λ - 2δ' - λξ), so that p_L lands on the 80% line ξ.
Focus focus_80(const CentreLine& l, const TopBase& lines, double focus, Trace* trace) {
    const double lambda = lines.lambda();
    Focus f;
    f.p_l = l.near_centre + focus * (l.far_centre - l.near_centre);
    f.delta_prime = l.along(f.p_l) - lines.top;
    f.eta = (lambda * f.delta_prime + lambda * f.delta_prime * kXi) / (lambda - 2 * f.delta_prime - lambda * kXi);
    f.q = l.near_centre + (lines.top - f.eta) * l.axis;
    record(trace, [&](Trace& t) {
        t.add("tsm-focus-80", "80% rule",
              "p_L ends the focus region, `focus` of the way from the near to the far centre; δ' = its distance "
              "from l_t; η = (λδ' + λδ'ξ) / (λ - 2δ' - λξ), ξ = -0.6; q on l, η before l_t",
              Space::light)
            .value("focus", focus)
            .value("xi", kXi)
            .value("p_L", f.p_l)
            .value("delta_prime", f.delta_prime)
            .value("lambda", lambda)
            .value("eta", f.eta)
            .value("q", f.q)
            .shape("p_L", PointSet{in_xy_plane({f.p_l})})
            .shape("p_L label", Label{{f.p_l, 0.0}, "p_L"})
            .shape("q", PointSet{in_xy_plane({f.q})})
            .shape("q label", Label{{f.q, 0.0}, "q"})
            .shape("l", SegmentSet{{{{f.q, 0.0}, {f.p_l, 0.0}}}});
    });
    return f;
}

// Why the 80% rule gives no trapezoid: p_L before l_t, or p_L so far that no warp is asked for.
std::string out_of_range(const Focus& f, const TopBase& lines) {
    const std::string at = "δ' = " + std::to_string(f.delta_prime / lines.lambda()) + " λ";
    return f.delta_prime > 0.0 ? at + ", not below 0.8 λ: the 80% rule asks for no warp; focused map used"
                               : at + ": p_L lies before the top line; focused map used";
}

struct Trapezoid {
    glm::dvec2 q, axis;
    double eta, lambda;
    double right_slope, left_slope;     // the side lines through q: across l = slope * along l
    std::array<glm::dvec2, 4> corners;  // top right, top left, base left, base right
};

// TSM: the two side lines through q touching the hull, cut by l_t and l_b: the trapezoid's corners.
Trapezoid trapezoid_around(const std::vector<glm::dvec2>& hull, const CentreLine& l, const TopBase& lines,
                           const Focus& f, Trace* trace) {
    Trapezoid z{f.q, l.axis, f.eta, lines.lambda(), INFINITY, -INFINITY, {}};
    for (const glm::dvec2& p : hull) {
        const double slope = cross(l.axis, p - f.q) / glm::dot(l.axis, p - f.q);
        z.right_slope = std::min(z.right_slope, slope);
        z.left_slope = std::max(z.left_slope, slope);
    }
    const glm::dvec2 across{-l.axis.y, l.axis.x};
    auto corner = [&](double along, double slope) { return f.q + along * l.axis + slope * along * across; };
    const double top = z.eta, base = z.eta + z.lambda;
    z.corners = {corner(top, z.right_slope), corner(top, z.left_slope), corner(base, z.left_slope),
                 corner(base, z.right_slope)};
    record(trace, [&](Trace& t) {
        t.add("tsm-trapezoid", "Trapezoid",
              "the side lines through q touching the hull, cut by l_t and l_b; corners: top right, top left, "
              "base left, base right",
              Space::light)
            .value("right_slope", z.right_slope)
            .value("left_slope", z.left_slope)
            .value("corner0", z.corners[0])
            .value("corner1", z.corners[1])
            .value("corner2", z.corners[2])
            .value("corner3", z.corners[3])
            .shape("trapezoid", PolygonSet{}.add(polygon_of(in_xy_plane({z.corners.begin(), z.corners.end()}))))
            .shape("q", PointSet{in_xy_plane({z.q})})
            .shape("q label", Label{{z.q, 0.0}, "q"});
    });
    return z;
}

// The depth row k (z - z_min), with k fitting the body's largest (z - z_min) / w to 1.
glm::dvec4 depth_row(const glm::dvec4& w, const std::vector<glm::dvec3>& ls_body) {
    double z_min = INFINITY, largest = 0.0;
    for (const glm::dvec3& p : ls_body) z_min = std::min(z_min, p.z);
    for (const glm::dvec3& p : ls_body) largest = std::max(largest, (p.z - z_min) / glm::dot(w, glm::dvec4(p, 1.0)));
    return {0.0, 0.0, 1.0 / largest, -z_min / largest};
}

// TSM: N_T, the trapezoid onto the unit square, in one projective step where the paper chains
// T1 R T2 H S1 N T3 S2: w = a, the distance from q along l; u w = (s - m_r a) / (m_l - m_r), s
// across l, m_l and m_r the side lines' slopes; v w = (η + λ)(a - η) / λ. Light space -> the map's unit cube.
glm::dmat4 trapezoid_to_square(const Trapezoid& z, const Focus& f, const std::vector<glm::dvec3>& ls_body,
                               Trace* trace) {
    const glm::dvec4 a{z.axis.x, z.axis.y, 0.0, -glm::dot(z.axis, z.q)};
    const glm::dvec4 s{-z.axis.y, z.axis.x, 0.0, -cross(z.axis, z.q)};
    const glm::dvec4 u = (s - z.right_slope * a) / (z.left_slope - z.right_slope);
    const glm::dvec4 v = (a - glm::dvec4(0.0, 0.0, 0.0, z.eta)) * ((z.eta + z.lambda) / z.lambda);
    const glm::dmat4 unit_from_light = from_rows(u, v, depth_row(a, ls_body), a);  // N_T
    record(trace, [&](Trace& t) {
        Step& step = t.add("tsm-trapezoid-to-square", "Trapezoid to square N_T",
                           "w = distance from q along l; u, v: the trapezoid onto [0,1]^2 (top line v = 0); light "
                           "rays keep (x, y) and so w: depth k (z - z_min) / w grows along each, k fitting B to [0,1]; "
                           "the paper writes z_L w per vertex instead, which one matrix cannot",
                           Space::unit)
                         .value("N_T", unit_from_light);
        auto on_square = [&](const glm::dvec2& ls_xy) {
            return glm::dvec3(glm::dvec2(transform_point(unit_from_light, {ls_xy, 0.0})), 0.0);
        };
        std::vector<glm::dvec3> square;
        for (size_t i = 0; i < z.corners.size(); ++i) {
            square.push_back(on_square(z.corners[i]));
            step.value("corner" + std::to_string(i) + "_uv", glm::dvec2(square.back()));
        }
        // The trapezoid lands on the unit square, and the focus region's end p_L on the 80% line v = (1 - ξ) / 2.
        const double v80 = (1.0 - kXi) / 2.0;
        step.shape("trapezoid on the square", PolygonSet{}.add(polygon_of(square)), Role::map)
            .shape("80% line", SegmentSet{{{{0.0, v80, 0.0}, {1.0, v80, 0.0}}}})
            .shape("80% label", Label{{1.0, v80, 0.0}, "80% line"})
            .shape("p_L", PointSet{{on_square(f.p_l)}})
            .shape("p_L label", Label{on_square(f.p_l), "p_L"});
        draw_unit_cube(step);
    });
    return unit_from_light;
}

}  // namespace

ShadowSetup compute_tsm(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    const auto body = start_perspective_warp("tsm", in, s, setup, trace);
    if (!body) return setup;

    const LightView ls = light_view(in, *body, trace);
    const CentreLine l = centre_line(in, *body, ls, trace);
    if (l.degenerate()) {
        fall_back_to_focused(
            Note{NoteKind::degenerate_centre_line, "|l| / points' extent = " + std::to_string(l.length / l.extent) +
                                                       " < 0.05, the light is almost parallel to the view; focused map "
                                                       "used"},
            in, *body, setup, trace);
        return setup;
    }
    const std::vector<glm::dvec2> hull = convex_hull(ls.points, trace);
    const TopBase lines = top_and_base(hull, l, trace);
    const Focus focus = focus_80(l, lines, s.number("focus"), trace);
    if (!(focus.eta > 0.0 && focus.eta < kNoWarp * lines.lambda())) {
        fall_back_to_focused(Note{NoteKind::focus_out_of_range, out_of_range(focus, lines)}, in, *body, setup, trace);
        return setup;
    }
    const Trapezoid trapezoid = trapezoid_around(hull, l, lines, focus, trace);
    const glm::dmat4 unit_from_light = trapezoid_to_square(trapezoid, focus, ls.body, trace);  // N_T

    ShadowMap map;
    map.world_to_uvz = unit_from_light * ls.light_from_world;
    // The trapezoid's warp: TSM's post-perspective space is the map's unit cube itself.
    record(trace, [&](Trace& t) { t.set_frame(Space::ppls, unit_from_light * ls.light_from_world); });
    map.z_bias_scale = row(unit_from_light, 2).z;  // depth per world unit along the light, before division by w
    setup.maps.push_back(map);
    record_output(setup, body->body.vertices, trace);
    return setup;
}

std::vector<SettingSpec> tsm_settings() {
    return {{"focus",
             "80% rule: the focus region, this fraction of the view's depth, ends on the map's 80% line",
             "0.5",
             0.05,
             1.0,
             {}},
            body_kernel_setting()};
}

}  // namespace shadowlab
