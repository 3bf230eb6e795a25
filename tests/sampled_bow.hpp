#pragma once
// How far a projected edge bows from its chord, sampled: what a kind's closed-form edge_sagitta is
// held against.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace shadowlab::testing {

// The greatest distance of the curve image(t), t in [0, 1], from its chord, over `samples` + 1 points.
template <class Image>
double sampled_bow(Image&& image, int samples) {
    const glm::dvec2 from = image(0.0), to = image(1.0);
    const glm::dvec2 across = glm::normalize(glm::dvec2(from.y - to.y, to.x - from.x));
    double greatest = 0.0;
    for (int k = 0; k <= samples; ++k)
        greatest = std::max(greatest, std::abs(glm::dot(image(double(k) / samples) - from, across)));
    return greatest;
}

}  // namespace shadowlab::testing
