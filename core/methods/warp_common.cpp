#include "methods/warp_common.hpp"

#include "methods/focused.hpp"
#include "methods/map_fit.hpp"

namespace shadowlab {

std::optional<IntersectionBody> start_warp(const std::string& method, const ShadowInputs& in,
                                           const Settings& settings, ShadowSetup& setup, Trace* trace) {
    auto body = body_or_uniform(in, settings, setup, trace);
    if (body && !in.light.is_directional()) {
        fall_back_to_focused(Note{NoteKind::not_directional,
                                             method + " warps directional lights only; focused map used for this " +
                                                 to_string(in.light.type) + " light"},
                             in, *body, setup, trace);
        return std::nullopt;
    }
    return body;
}

void fall_back_to_focused(Note reason, const ShadowInputs& in, const IntersectionBody& body,
                          ShadowSetup& setup, Trace* trace) {
    add_fallback(setup, std::move(reason));
    fit_focused(in, body, setup, trace);
}

std::vector<glm::dvec3> corners_within(const std::vector<Aabb>& boxes, const Aabb& region) {
    std::vector<glm::dvec3> points;
    for (const Aabb& b : boxes) {
        const Aabb cut{glm::max(b.min, region.min), glm::min(b.max, region.max)};
        if (cut.empty()) continue;
        for (const glm::dvec3& c : cut.corners()) points.push_back(c);
    }
    return points;
}

ProjectedPoints project(const std::vector<glm::dvec3>& points, const glm::dmat4& m, double min_w) {
    ProjectedPoints out;
    out.points.reserve(points.size());
    for (const glm::dvec3& p : points) {
        const glm::dvec4 h = m * glm::dvec4(p, 1.0);
        if (h.w < min_w) ++out.left_out;
        else out.points.push_back(glm::dvec3(h) / h.w);
    }
    return out;
}

}  // namespace shadowlab
