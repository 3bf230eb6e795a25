#include "flatland/level_curves.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "math/invariant.hpp"

namespace shadowlab {
namespace {

constexpr int kBisections = 32;  // a crossing to 2^-32 of its cell edge

// A cell edge by its lower corner and direction: horizontal (to (i + 1, j)) or vertical (to (i, j + 1)).
struct GridEdge {
    int i, j;
    bool vertical;
};

std::int64_t edge_key(const GridEdge& e, int columns) {
    return 2 * (static_cast<std::int64_t>(e.j) * (columns + 1) + e.i) + (e.vertical ? 1 : 0);
}

struct Segment {
    std::int64_t a, b;  // the edges it joins
};

class CurveTracer {
public:
    CurveTracer(const GridSamples& s, const ScalarField& field, double level) : s_(s), field_(field), level_(level) {}

    // The cell's corners (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1), their values v (none NaN),
    // and its edges bottom, right, top, left: edge k joins corners k and k + 1.
    void cross_cell(int i, int j, const std::array<double, 4>& v) {
        const std::array<GridEdge, 4> edges{{{i, j, false}, {i + 1, j, true}, {i, j + 1, false}, {i, j, true}}};
        std::array<int, 4> crossed{};
        int count = 0;
        for (int k = 0; k < 4; ++k)
            if (above(v[k]) != above(v[(k + 1) % 4])) crossed[count++] = k;
        if (count == 0) return;
        if (count == 2) return join(edges[crossed[0]], edges[crossed[1]]);
        assert_invariant(count == 4);
        // A saddle: the mean of the corners decides whether corners 0 and 2 are joined across it.
        const bool centre_above = above((v[0] + v[1] + v[2] + v[3]) / 4.0);
        if (centre_above == above(v[0])) {  // 0 and 2 joined: cut off corners 1 and 3
            join(edges[0], edges[1]);
            join(edges[2], edges[3]);
        } else {  // cut off corners 0 and 2
            join(edges[3], edges[0]);
            join(edges[1], edges[2]);
        }
    }

    void join(const GridEdge& a, const GridEdge& b) {
        const Segment segment{crossing(a), crossing(b)};
        at_edge_[segment.a].push_back(static_cast<int>(segments_.size()));
        at_edge_[segment.b].push_back(static_cast<int>(segments_.size()));
        segments_.push_back(segment);
    }

    // The edge's crossing of the level, found by bisection between its corners; its key.
    std::int64_t crossing(const GridEdge& e) {
        const std::int64_t key = edge_key(e, s_.grid.cells.x);
        if (points_.count(key)) return key;
        glm::dvec3 lo = s_.grid.point(e.i, e.j), hi = s_.grid.point(e.i + !e.vertical, e.j + e.vertical);
        if (above(s_.at(e.i, e.j))) std::swap(lo, hi);
        for (int k = 0; k < kBisections; ++k) {
            const glm::dvec3 mid = 0.5 * (lo + hi);
            const double value = field_(mid);
            if (std::isnan(value)) break;  // the domain's edge inside the cell edge: the crossing to that precision
            (above(value) ? hi : lo) = mid;
        }
        points_[key] = 0.5 * (lo + hi);
        return key;
    }

    // The segments chained into polylines.
    std::vector<Polyline> chained() {
        std::vector<bool> used(segments_.size(), false);
        std::vector<Polyline> curves;
        const auto walk = [&](std::int64_t edge, int segment) {
            Polyline line{points_[edge]};
            while (segment >= 0) {
                used[segment] = true;
                edge = segments_[segment].a == edge ? segments_[segment].b : segments_[segment].a;
                line.push_back(points_[edge]);
                segment = -1;
                for (int next : at_edge_[edge])
                    if (!used[next]) segment = next;
            }
            curves.push_back(std::move(line));
        };
        for (const auto& [edge, touching] : at_edge_)  // open curves, from an end
            if (touching.size() == 1 && !used[touching[0]]) walk(edge, touching[0]);
        for (size_t k = 0; k < segments_.size(); ++k)  // loops, from anywhere
            if (!used[k]) walk(segments_[k].a, static_cast<int>(k));
        return curves;
    }

private:
    bool above(double value) const { return value >= level_; }

    const GridSamples& s_;
    const ScalarField& field_;
    double level_;
    std::vector<Segment> segments_;
    std::unordered_map<std::int64_t, std::vector<int>> at_edge_;
    std::unordered_map<std::int64_t, glm::dvec3> points_;
};

}  // namespace

glm::dvec3 PlaneGrid::point(int i, int j) const {
    const glm::dvec2 st = min + cell_size() * glm::dvec2(i, j);
    return origin + st.x * along + st.y * across;
}

GridSamples sample_field(const PlaneGrid& grid, const ScalarField& field) {
    GridSamples samples{grid, {}};
    samples.values.reserve(static_cast<size_t>(grid.cells.x + 1) * (grid.cells.y + 1));
    for (int j = 0; j <= grid.cells.y; ++j)
        for (int i = 0; i <= grid.cells.x; ++i) samples.values.push_back(field(grid.point(i, j)));
    return samples;
}

std::vector<Polyline> level_curves(const GridSamples& samples, const ScalarField& field, double level) {
    return level_curves(samples, field, std::vector<double>{level}).front();
}

std::vector<std::vector<Polyline>> level_curves(const GridSamples& samples, const ScalarField& field,
                                                const std::vector<double>& levels) {
    assert_invariant(std::is_sorted(levels.begin(), levels.end()));
    std::vector<CurveTracer> tracers;
    for (double level : levels) tracers.emplace_back(samples, field, level);
    for (int j = 0; j < samples.grid.cells.y; ++j)
        for (int i = 0; i < samples.grid.cells.x; ++i) {
            const std::array<double, 4> v{samples.at(i, j), samples.at(i + 1, j), samples.at(i + 1, j + 1),
                                          samples.at(i, j + 1)};
            if (std::isnan(v[0] + v[1] + v[2] + v[3])) continue;
            const auto [lo, hi] = std::minmax({v[0], v[1], v[2], v[3]});
            // A level crosses the cell when some corner lies below it and some at or above: lo < level <= hi.
            for (auto level = std::upper_bound(levels.begin(), levels.end(), lo); level != levels.end() && *level <= hi;
                 ++level)
                tracers[level - levels.begin()].cross_cell(i, j, v);
        }
    std::vector<std::vector<Polyline>> curves;
    for (CurveTracer& tracer : tracers) curves.push_back(tracer.chained());
    return curves;
}

}  // namespace shadowlab
