#pragma once
// What a geometric technique's last step draws: the visible points it shadows, in the camera's view
// space. Only the trace lambdas call it.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "reference/exact_shadows.hpp"
#include "scene/camera.hpp"
#include "trace/trace.hpp"

namespace shadowlab {

// The visible points of the pixels `shadowed` marks (every k-th, at most `at_most`), in view space,
// or a label saying there are none.
inline Step& draw_shadowed_points(Step& step, const std::vector<uint8_t>& shadowed, const ReferenceImage& image,
                                  const Camera& camera, std::size_t at_most = 4000) {
    const std::size_t count = std::size_t(std::count(shadowed.begin(), shadowed.end(), uint8_t(1)));
    if (count == 0) return step.shape("shadowed label", Label{{0.0, 0.0, -camera.near}, "no shadowed pixel"});
    const std::size_t stride = (count + at_most - 1) / at_most;
    const glm::dmat4 view_from_world = camera.view_matrix();
    PointSet points;
    for (std::size_t i = 0, seen = 0; i < shadowed.size(); ++i)
        if (shadowed[i] && seen++ % stride == 0)
            points.points.push_back(glm::dvec3(view_from_world * glm::dvec4(image.position[i], 1.0)));
    return step.shape("shadowed points", std::move(points), Role::receivers);
}

}  // namespace shadowlab
