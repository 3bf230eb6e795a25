#include "methods/page_marking.hpp"

#include <algorithm>
#include <numeric>

namespace shadowlab {

double footprint_width(const Camera& camera, int image_height, const glm::dvec3& p) {
    const double depth = glm::dot(p - camera.position, camera.view_direction());
    return 2.0 * camera.half_extent_at(depth).y / image_height;
}

int PageMarks::count() const { return static_cast<int>(std::count(marked.begin(), marked.end(), 1)); }

std::vector<double> footprint_levels(const Clipmap& c, const Camera& camera, const SeenReceivers& seen) {
    std::vector<double> levels;
    levels.reserve(seen.points.size());
    for (const glm::dvec3& p : seen.points)
        levels.push_back(footprint_level(c, footprint_width(camera, seen.image_height, p)));
    return levels;
}

PageMarks mark_pages(const Clipmap& c, const SeenReceivers& seen, const std::vector<double>& levels,
                     double resolution_bias) {
    PageMarks marks{.marked = std::vector<std::uint8_t>(c.table.resident.size(), 0)};
    for (std::size_t i = 0; i < seen.points.size(); ++i) {
        const glm::dvec3& p = seen.points[i];
        bool held = false;
        const int asked = std::min(level_asked(levels[i], resolution_bias), c.levels() - 1);
        for (int level = asked; level < c.levels() && !held; ++level)
            if (const std::optional<PageAddress> page = page_holding(c.table, level, p)) {
                marks.marked[c.table.index(*page)] = 1;
                held = true;
            }
        ++(held ? marks.points : marks.outside);
    }
    return marks;
}

std::vector<PageAddress> marked_pages(const PageTable& table, const std::vector<std::uint8_t>& marked) {
    std::vector<PageAddress> pages;
    const int n = table.pages_per_side;
    for (int level = 0; level < static_cast<int>(table.levels.size()); ++level)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                if (const PageAddress a{.level = level, .page = {x, y}}; marked[table.index(a)]) pages.push_back(a);
    return pages;
}

namespace {

// The pages farthest from the camera (in light space) beyond the first `keep` of them, removed.
void keep_nearest(std::vector<PageAddress>& pages, const Clipmap& c, int keep) {
    auto distance = [&](const PageAddress& a) {
        return glm::distance((glm::dvec2(grid_page(c.table, a)) + 0.5) * c.page_width(a.level), c.ls_camera);
    };
    std::stable_sort(pages.begin(), pages.end(),
                     [&](const PageAddress& a, const PageAddress& b) { return distance(a) < distance(b); });
    pages.resize(std::size_t(keep));
    std::stable_sort(pages.begin(), pages.end(),
                     [&](const PageAddress& a, const PageAddress& b) { return c.table.index(a) < c.table.index(b); });
}

}  // namespace

PageAllocation allocate_pages(const Clipmap& c, const Camera& camera, const SeenReceivers& seen, double resolution_bias,
                              int budget) {
    constexpr int kStepsPerLevel = 8;
    const std::vector<double> levels = footprint_levels(c, camera, seen);
    PageAllocation out{.marks = mark_pages(c, seen, levels, resolution_bias), .budget = budget};
    PageMarks fitted = out.marks;
    if (fitted.count() > budget) {
        // The least added bias that fits, by bisection over its steps (the count falls as the bias rises).
        auto marks_at = [&](int steps) {
            return mark_pages(c, seen, levels, resolution_bias + double(steps) / kStepsPerLevel);
        };
        int lo = 0, hi = c.levels() * kStepsPerLevel;
        while (hi - lo > 1) {
            const int mid = (lo + hi) / 2;
            (marks_at(mid).count() <= budget ? hi : lo) = mid;
        }
        fitted = marks_at(hi);
        out.bias_added = double(hi) / kStepsPerLevel;
    }
    out.resident = marked_pages(c.table, fitted.marked);
    if (static_cast<int>(out.resident.size()) > budget) {
        out.dropped = static_cast<int>(out.resident.size()) - budget;
        keep_nearest(out.resident, c, budget);
    }
    out.over_budget = std::max(0, out.marked() - static_cast<int>(out.resident.size()));
    return out;
}

}  // namespace shadowlab
