#include "lookup/depth_bias.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "maps/map_lookup.hpp"
#include "math/singular_values.hpp"

namespace shadowlab {
namespace {

// Two unit directions across the light, perpendicular to it and to each other.
std::pair<glm::dvec3, glm::dvec3> across(const glm::dvec3& l) {
    const glm::dvec3 a = glm::normalize(glm::cross(l, std::abs(l.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    return {a, glm::cross(l, a)};
}

}  // namespace

std::string describe(const DepthBias& bias) {
    const auto number = [](double x) {
        std::ostringstream out;
        out << x;
        return out.str();
    };
    std::vector<std::string> parts;
    if (bias.constant > 0.0) parts.push_back("constant " + number(bias.constant));
    if (bias.slope_scale > 0.0) parts.push_back("slope-scaled x" + number(bias.slope_scale));
    if (bias.normal_offset > 0.0) parts.push_back("normal offset " + number(bias.normal_offset) + " texels");
    if (bias.receiver_plane) parts.push_back("receiver plane");
    std::string text;
    for (const std::string& part : parts) text += (text.empty() ? "" : " + ") + part;
    return text.empty() ? "none" : text;
}

double texel_world_size(const ShadowMap& map, double texels, const glm::dvec3& l, const glm::dvec3& p) {
    // How far (u, v) moves per world unit across the light: derivatives, not differences, so no step
    // size is tied to the scene's scale. A texel is 1 / texels wide; its longest world extent is that
    // over the Jacobian's smallest singular value.
    const auto [a, b] = across(l);
    const double sigma_min = smallest_singular_value(glm::dmat2(uv_derivative(map, p, a), uv_derivative(map, p, b)));
    return sigma_min > 0.0 ? 1.0 / (texels * sigma_min) : INFINITY;
}

double slope_scaled_bias(double texel_world, double cos_theta) {
    const double tan_theta =
        std::min(10.0, std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta)) / std::max(cos_theta, 1e-6));
    return texel_world * (1.0 + tan_theta);
}

double slope_scaled_bias(const ShadowMap& map, double texels, const glm::dvec3& l, const glm::dvec3& p,
                         double cos_theta) {
    return slope_scaled_bias(texel_world_size(map, texels, l, p), cos_theta);
}

glm::dvec2 receiver_plane_gradient(const ShadowMap& map, const glm::dvec3& p, const glm::dvec3& normal) {
    // Two directions in the plane; along each, (u, v) and d move by the map's derivatives. Then
    // Δd = g · Δuv for both: g = (∂d/∂s₁, ∂d/∂s₂) J⁻¹, J's columns the (u, v) derivatives.
    const auto [s1, s2] = across(normal);
    const glm::dmat2 j(uv_derivative(map, p, s1), uv_derivative(map, p, s2));
    const double det = glm::determinant(j);
    const glm::dvec2 along(depth_slope(map, s1, p), depth_slope(map, s2, p));
    if (!(std::abs(det) > 1e-12 * (glm::dot(j[0], j[0]) + glm::dot(j[1], j[1])))) return glm::dvec2(0.0);
    const glm::dvec2 g = along * glm::inverse(j);  // row vector times J⁻¹
    return std::isfinite(g.x) && std::isfinite(g.y) ? g : glm::dvec2(0.0);
}

}  // namespace shadowlab
