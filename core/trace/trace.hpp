#pragma once
// A step trace: what a method did, step by step, in the space where each step happens.
// Methods record through `record(trace, ...)`: with no trace asked for, the lambda is never
// called, so nothing is computed, recorded or allocated for it.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>
#include <glm/glm.hpp>

#include "geometry/aabb.hpp"
#include "geometry/convex_polyhedron.hpp"
#include "geometry/frustum.hpp"

namespace shadowlab {

enum class Space { world, view, light, ppls, unit };
const char* to_string(Space space);

struct PointSet {
    std::vector<glm::dvec3> points;
};

// Line segments in world space (silhouette edges), each from .first to .second.
struct SegmentSet {
    std::vector<std::pair<glm::dvec3, glm::dvec3>> segments;
};

// Planar convex polygons with homogeneous vertices (x, y, z, w): w = 0 is a point at infinity,
// as a shadow volume's extruded quads and back caps have. Each polygon lists vertex indices in
// order, counter-clockwise seen from the side its normal points to.
struct PolygonSet {
    std::vector<glm::dvec4> vertices;
    std::vector<std::vector<int>> polygons;

    PolygonSet& add(const std::vector<glm::dvec4>& polygon) {
        std::vector<int>& loop = polygons.emplace_back();
        for (const glm::dvec4& v : polygon) {
            loop.push_back(static_cast<int>(vertices.size()));
            vertices.push_back(v);
        }
        return *this;
    }
};

// A vector drawn as an arrow from `from` to `to`: the view vector V, the light L, unitP.
struct Arrow {
    glm::dvec3 from, to;
};

// An angle drawn as a circular arc about `centre`, from direction `from` to direction `to`, at
// distance `radius` (γ between V and L).
struct AngleArc {
    glm::dvec3 centre, from, to;
    double radius = 1.0;
};

// Text placed at a point of the step's space: "n = 3.2", "C", "[0,1]³".
struct Label {
    glm::dvec3 at;
    std::string text;
};

using TraceValue = std::variant<double, glm::dvec2, glm::dvec3, glm::dvec4, glm::dmat4, std::string>;
using TraceGeometry =
    std::variant<PointSet, Aabb, ConvexPolyhedron, Frustum, SegmentSet, PolygonSet, Arrow, AngleArc, Label>;

struct NamedValue {
    std::string name;
    TraceValue value;
};

// What a shape stands for. It fixes the shape's colour and legend entry in every view, as the
// papers colour their figures: casters blue, receivers red, the focus region green.
enum class Role {
    step,       // the step's own construction (the highlight colour)
    casters,    // shadow casters, their points, boxes and intervals
    receivers,  // shadow receivers, likewise
    focus,      // the region the map is fitted to (XPSM's focus region, the body B)
    light,      // the light: its direction L, its position, its frustum
    view,       // the camera: its frustum, the view vector V
    map,        // the map's volume and the unit cube [0,1]^3
};
const char* to_string(Role role);

struct NamedGeometry {
    std::string name;
    TraceGeometry geometry;
    Role role = Role::step;
    int map = -1;  // the setup's map the shape belongs to (a cascade's slice, box, tile): drawn in that map's colour
};

struct Step {
    std::string id;           // stable, e.g. "body" or "xpsm-5"
    std::string title;        // as the paper names it, e.g. "maxLengthP"
    std::string explanation;  // one line: the formula this step applies
    Space space = Space::world;
    std::vector<NamedValue> values;
    std::vector<NamedGeometry> geometry;

    Step& value(std::string name, TraceValue v) {
        values.push_back({std::move(name), std::move(v)});
        return *this;
    }
    Step& shape(std::string name, TraceGeometry g, Role role = Role::step) {
        geometry.push_back({std::move(name), std::move(g), role});
        return *this;
    }
    // A shape of one map of the setup (map = its index): its role, drawn in the map's own colour.
    Step& map_shape(int map, std::string name, TraceGeometry g, Role role = Role::step) {
        geometry.push_back({std::move(name), std::move(g), role, map});
        return *this;
    }
};

class Trace {
public:
    Step& add(std::string id, std::string title, std::string explanation, Space space) {
        steps_.push_back({std::move(id), std::move(title), std::move(explanation), space, {}, {}});
        return steps_.back();
    }
    const std::vector<Step>& steps() const { return steps_; }
    const Step* find(const std::string& id) const {
        for (const Step& s : steps_)
            if (s.id == id) return &s;
        return nullptr;
    }
    // The method's own map from world points into `space` (homogeneous: divide by w), so a viewer
    // can draw the whole scene there. A method sets the spaces it uses; the last setting wins (a
    // fallback's frames replace the warp's).
    void set_frame(Space space, const glm::dmat4& world_to_space) { frames_[static_cast<int>(space)] = world_to_space; }
    const std::optional<glm::dmat4>& frame(Space space) const { return frames_[static_cast<int>(space)]; }

private:
    std::vector<Step> steps_;
    std::array<std::optional<glm::dmat4>, 5> frames_;
};

// Calls fill(*trace) only when a trace was asked for.
template <class Fill>
inline void record(Trace* trace, Fill&& fill) {
    if (trace) fill(*trace);
}

}  // namespace shadowlab
