#include "metrics/storage_bound.hpp"

#include <cmath>

#include "metrics/light_image.hpp"
#include "metrics/max_density_grid.hpp"
#include "metrics/pixel_steps.hpp"

namespace shadowlab {
namespace {

// One pixel on the light's image plane: its footprint on its surface (the parallelogram of its two
// steps' images) and the texels per unit area it asks there, 1 / |det G| (G: its steps on the
// halfway plane, carried there). nullopt where a step's light ray misses the pixel's chart.
struct LightFootprint {
    LightImagePoint centre;
    glm::dvec2 right, down;
    double density = 0.0;
};

std::optional<LightFootprint> light_footprint(const LightImage& image, const PixelSteps& steps) {
    const LightImagePoint centre = image.of(steps.point);
    const auto step = [&](const glm::dvec3& to) -> std::optional<glm::dvec2> {
        const std::optional<glm::dvec2> at = image.on(centre.chart, to);
        return at ? std::optional(*at - centre.at) : std::nullopt;
    };
    const std::optional<glm::dvec2> right = step(steps.right), down = step(steps.down),
                                    right_on_halfway = step(steps.right_on_halfway),
                                    down_on_halfway = step(steps.down_on_halfway);
    if (!right || !down || !right_on_halfway || !down_on_halfway) return std::nullopt;
    const double allowed_texel_area = std::abs(glm::determinant(glm::dmat2(*right_on_halfway, *down_on_halfway)));
    return LightFootprint{.centre = centre, .right = *right, .down = *down, .density = 1.0 / allowed_texel_area};
}

// Whether the light reaches p: a spot only within its cone.
bool in_reach(const Light& light, const glm::dvec3& p) {
    return light.type != LightType::spot ||
           glm::dot(glm::normalize(p - light.position), light.direction) >= std::cos(glm::radians(light.cone_deg / 2));
}

}  // namespace

StorageBounds storage_lower_bounds(const Scene& scene, const ReferenceImage& reference) {
    const LightImage image(scene.light);
    MaxDensityGrid grid;  // densities: every receiver's, the shadowed receivers' (0 for a lit one)
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x)
            if (const std::optional<PixelSteps> steps = pixel_steps(scene, reference, x, y);
                steps && in_reach(scene.light, steps->point))
                if (const std::optional<LightFootprint> f = light_footprint(image, *steps)) {
                    const bool shadowed = !reference.lit[size_t(y) * reference.width + x];
                    grid.add(f->centre.chart, f->centre.at, f->right, f->down,
                             {f->density, shadowed ? f->density : 0.0});
                }
    const glm::dvec2 bounds = grid.integral();
    return {.every_receiver = bounds.x, .shadowed_receivers = bounds.y};
}

StorageFactor storage_factor(double texels, const AliasingStats& m_perspective, double lower_bound) {
    const double needed = texels * m_perspective.max * m_perspective.max;
    return {.needed = needed, .lower_bound = lower_bound, .efficiency = needed > 0.0 ? lower_bound / needed : 0.0};
}

}  // namespace shadowlab
