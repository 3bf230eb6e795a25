#include "exchange/inspection_json.hpp"

#include "maps/projection_kind.hpp"
#include "math/matrix.hpp"

namespace shadowlab {

template <int N>
static Json to_json(const glm::vec<N, double>& v) {
    Json out = Json::array();
    for (int i = 0; i < N; ++i) out.push_back(v[i]);
    return out;
}

static Json points_json(const std::vector<glm::dvec3>& points) {
    Json out = Json::array();
    for (const glm::dvec3& p : points) out.push_back(to_json(p));
    return out;
}

Json to_json(const glm::dmat4& m) {
    return Json::array({to_json(row(m, 0)), to_json(row(m, 1)), to_json(row(m, 2)), to_json(row(m, 3))});
}

Json to_json(const TraceValue& value) {
    return std::visit(
        [](const auto& v) -> Json {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::string>)
                return v;
            else
                return to_json(v);
        },
        value);
}

static Json polyhedron_json(const ConvexPolyhedron& poly) {
    Json faces = Json::array();
    for (const PolyFace& f : poly.faces) faces.push_back(f.loop);
    return {{"kind", "polyhedron"}, {"vertices", points_json(poly.vertices)}, {"faces", faces}};
}

static Json segments_json(const SegmentSet& set) {
    Json segments = Json::array();
    for (const auto& [a, b] : set.segments) segments.push_back({to_json(a), to_json(b)});
    return {{"kind", "segments"}, {"segments", segments}};
}

// Vertices as [x, y, z, w]: w = 0 is a point at infinity.
static Json polygons_json(const PolygonSet& set) {
    Json vertices = Json::array();
    for (const glm::dvec4& v : set.vertices) vertices.push_back(to_json(v));
    return {{"kind", "polygons"}, {"vertices", vertices}, {"polygons", set.polygons}};
}

Json to_json(const NamedGeometry& named) {
    Json out = std::visit(
        [](const auto& g) -> Json {
            using T = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<T, PointSet>)
                return {{"kind", "points"}, {"points", points_json(g.points)}};
            else if constexpr (std::is_same_v<T, Aabb>)
                return {{"kind", "aabb"}, {"min", to_json(g.min)}, {"max", to_json(g.max)}};
            else if constexpr (std::is_same_v<T, ConvexPolyhedron>)
                return polyhedron_json(g);
            else if constexpr (std::is_same_v<T, SegmentSet>)
                return segments_json(g);
            else if constexpr (std::is_same_v<T, PolygonSet>)
                return polygons_json(g);
            else if constexpr (std::is_same_v<T, Arrow>)
                return {{"kind", "arrow"}, {"from", to_json(g.from)}, {"to", to_json(g.to)}};
            else if constexpr (std::is_same_v<T, AngleArc>)
                return {{"kind", "angle"},
                        {"centre", to_json(g.centre)},
                        {"from", to_json(g.from)},
                        {"to", to_json(g.to)},
                        {"radius", g.radius}};
            else if constexpr (std::is_same_v<T, Label>)
                return {{"kind", "label"}, {"at", to_json(g.at)}, {"text", g.text}};
            else
                return {{"kind", "frustum"}, {"corners", points_json({g.corners.begin(), g.corners.end()})}};
        },
        named.geometry);
    out["name"] = named.name;
    out["role"] = to_string(named.role);
    return out;
}

Json to_json(const Step& step) {
    Json values = Json::object();
    for (const NamedValue& v : step.values) values[v.name] = to_json(v.value);
    Json geometry = Json::array();
    for (const NamedGeometry& g : step.geometry) geometry.push_back(to_json(g));
    return {
        {"id", step.id},    {"title", step.title}, {"explanation", step.explanation}, {"space", to_string(step.space)},
        {"values", values}, {"geometry", geometry}};
}

Json to_json(const ShadowMap& map) {
    const ProjectionKind& kind = projection_kind(map);
    Json out = {{"projection", kind.name}};
    Json& parameters = kind.parameters_key ? out[kind.parameters_key] : out;
    for (const NamedValue& v : kind.parameters(map)) parameters[v.name] = to_json(v.value);
    if (kind.numbered_face) out["cube_face"] = map.cube_face;
    if (map.face_axis != glm::dvec3(0.0)) out["face_axis"] = to_json(map.face_axis);
    if (!map.mask.empty()) {  // the half-planes a u + b v + c >= 0 its casters are drawn in
        Json& mask = out["mask"] = Json::array();
        for (const glm::dvec3& half : map.mask) mask.push_back(to_json(half));
    }
    out["viewport"] = to_json(map.viewport);
    out["z_bias_scale"] = map.z_bias_scale;
    return out;
}

Json pages_json(const PageTable& t) {
    std::vector<int> per_level(t.levels.size(), 0);
    for (const PageAddress& a : t.pages) ++per_level[a.level];
    return {
        {"resident", t.pages.size()},          {"budget", t.counts.budget},       {"page_size", t.page_size},
        {"levels", t.levels.size()},           {"resident_per_level", per_level}, {"marked", t.counts.marked},
        {"over_budget", t.counts.over_budget}, {"dropped", t.counts.dropped},     {"bias_added", t.counts.bias_added}};
}

Json to_json(const PageTable& t) {
    Json levels = Json::array(), pages = Json::array();
    for (const PageLevel& level : t.levels)
        levels.push_back(
            {{"world_to_uvz", to_json(level.world_to_uvz)}, {"first_page", {level.first_page.x, level.first_page.y}}});
    for (const PageAddress& a : t.pages) pages.push_back({a.level, a.page.x, a.page.y});
    Json out = pages_json(t);
    out.update({{"pages_per_side", t.pages_per_side}, {"level_maps", levels}, {"map_pages", pages}});
    return out;
}

Json to_json(const MapSelection& s) {
    Json out = {{"rule", to_string(s.rule)}};
    if (s.rule == MapSelection::Rule::view_depth)
        out.update({{"eye", to_json(s.eye)}, {"view_axis", to_json(s.view_axis)}, {"split_depths", s.split_depths}});
    if (s.rule == MapSelection::Rule::face_axis) out["centre"] = to_json(s.centre);
    if (s.rule == MapSelection::Rule::pages) out["pages"] = to_json(s.pages);
    return out;
}

Json to_json(const std::vector<Note>& notes) {
    Json out = Json::array();
    for (const Note& n : notes) out.push_back({{"kind", to_string(n.kind)}, {"message", n.message}});
    return out;
}

// The notes as one line ("name: message; ..."), or null for none: the field scripts read first.
static Json described(const std::vector<Note>& notes) { return notes.empty() ? Json(nullptr) : Json(describe(notes)); }

static Json settings_json(const Settings& settings) {
    Json out = Json::object();
    for (const auto& [key, value] : settings.values())
        out[key] = std::visit([](const auto& v) { return Json(v); }, value);
    return out;
}

static Json steps_json(const Trace& trace) {
    Json steps = Json::array();
    for (const Step& s : trace.steps()) steps.push_back(to_json(s));
    return steps;
}

Json inspection_json(const std::string& method, const Settings& settings, const ShadowInputs& inputs,
                     const ShadowSetup& setup, const Trace& trace) {
    Json maps = Json::array();
    for (const ShadowMap& m : setup.maps) maps.push_back(to_json(m));
    return {{"method", method},
            {"settings", settings_json(settings)},
            {"fallback", described(setup.fallbacks)},
            {"fallbacks", to_json(setup.fallbacks)},
            {"inputs",
             {{"receivers", points_json(inputs.receiver_points())}, {"casters", points_json(inputs.caster_points())}}},
            {"maps", maps},
            {"selection", to_json(setup.selection)},
            {"steps", steps_json(trace)}};
}

Json technique_inspection_json(const std::string& technique, const Settings& settings, const GeometryResult& result,
                               const Trace& trace) {
    return {{"method", technique},
            {"settings", settings_json(settings)},
            {"limits", to_json(result.limits)},
            {"cost",
             {{"polygons", result.cost.polygons},
              {"fill_mean", result.cost.fill_mean},
              {"fill_max", result.cost.fill_max}}},
            {"steps", steps_json(trace)}};
}

}  // namespace shadowlab
