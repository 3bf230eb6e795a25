#include "reference/light_samples.hpp"

#include <cmath>
#include <numbers>

#include "math/hash.hpp"

namespace shadowlab {
namespace {

double unit_interval(std::uint32_t bits) { return (bits >> 8) * (1.0 / 16777216.0); }

// Shirley and Chiu's concentric map of the square [-1, 1]² onto the unit disc: squares' rings onto
// the disc's rings, so equal cells stay equal areas.
glm::dvec2 concentric_disc(const glm::dvec2& square) {
    if (square.x == 0.0 && square.y == 0.0) return glm::dvec2(0.0);
    const double quarter = std::numbers::pi / 4;
    if (std::abs(square.x) > std::abs(square.y))
        return square.x * glm::dvec2(std::cos(quarter * square.y / square.x), std::sin(quarter * square.y / square.x));
    return square.y * glm::dvec2(std::sin(quarter * square.x / square.y), std::cos(quarter * square.x / square.y));
}

// Two unit vectors perpendicular to `axis` and to each other.
std::pair<glm::dvec3, glm::dvec3> across(const glm::dvec3& axis) {
    const glm::dvec3 hint = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 a = glm::normalize(glm::cross(axis, hint));
    return {a, glm::cross(axis, a)};
}

}  // namespace

std::vector<glm::dvec2> stratified_disc(int samples, std::uint32_t seed) {
    const int side = std::max(1, int(std::ceil(std::sqrt(double(samples)))));
    std::vector<glm::dvec2> disc;
    disc.reserve(size_t(side) * side);
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const std::uint32_t h = lowbias32(seed * 0x9e3779b9U + std::uint32_t(j * side + i));
            const glm::dvec2 jitter{unit_interval(h), unit_interval(lowbias32(h))};
            disc.push_back(concentric_disc(2.0 * (glm::dvec2(i, j) + jitter) / double(side) - 1.0));
        }
    return disc;
}

glm::dvec3 sun_direction(const Light& sun, const glm::dvec2& s) {
    const glm::dvec3 toward = -glm::normalize(sun.direction);
    const auto [a, b] = across(toward);
    return glm::normalize(toward + std::tan(glm::radians(sun.angular_radius_deg)) * (s.x * a + s.y * b));
}

glm::dvec3 sphere_light_point(const Light& light, const glm::dvec3& p, const glm::dvec2& s) {
    const auto [a, b] = across(glm::normalize(light.position - p));
    return light.position + light.radius * (s.x * a + s.y * b);
}

double visibility_standard_error(double visibility, int samples) {
    return std::sqrt(std::max(0.0, visibility * (1.0 - visibility)) / samples);
}

}  // namespace shadowlab
