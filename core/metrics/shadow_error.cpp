#include "metrics/shadow_error.hpp"

#include <algorithm>
#include <cmath>

namespace shadowlab {

double texel_extent_in_pixels(const glm::dvec2& uv, const glm::dvec2& uv_right, const glm::dvec2& uv_down,
                              double resolution) {
    const glm::dmat2 j(uv_right - uv, uv_down - uv);  // columns: per pixel right, per pixel down
    // Smallest singular value of a 2x2 matrix from its Frobenius norm and determinant.
    const double f = glm::dot(j[0], j[0]) + glm::dot(j[1], j[1]), det = std::abs(glm::determinant(j));
    const double sigma_min = std::sqrt(std::max(0.0, (f - std::sqrt(std::max(0.0, f * f - 4 * det * det))) / 2));
    return sigma_min > 0.0 ? 1.0 / (resolution * sigma_min) : INFINITY;
}

double slope_scaled_bias(const ShadowMap& map, double texels, const glm::dvec3& l, const glm::dvec3& p,
                         double cos_theta) {
    // Two directions across the light, and how far (u, v) moves along each per world unit: the
    // texel's extent in world units (derivatives, not differences: no step size to tie to a scale).
    const glm::dvec3 a = glm::normalize(glm::cross(l, std::abs(l.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 b = glm::cross(l, a);
    const glm::dvec2 uv(world_to_uvz(map, p));
    const double extent =
        texel_extent_in_pixels(uv, uv + uv_derivative(map, p, a), uv + uv_derivative(map, p, b), texels);
    const double tan_theta = std::min(10.0, std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta)) / std::max(cos_theta, 1e-6));
    return extent * (1.0 + tan_theta);
}

namespace {

glm::dvec3 along_light(const Light& light, const glm::dvec3& p) {
    return light.is_directional() ? light.direction : glm::normalize(p - light.position);
}

}  // namespace

MapBias bias_at(const ShadowSetup& setup, int texture_resolution, const Light& light, const glm::dvec3& p,
                double cos_theta, double bias) {
    if (bias >= 0.0) return [bias](int) { return bias; };
    return [&setup, texture_resolution, light_direction = along_light(light, p), p, cos_theta](int which) {
        const ShadowMap& map = setup.maps[which];
        const double slope_scaled =
            slope_scaled_bias(map, tile_resolution(map, texture_resolution), light_direction, p, cos_theta);
        return std::isfinite(slope_scaled) ? slope_scaled : 0.0;
    };
}

namespace {

constexpr double kDepthBufferSteps = 16777216.0;  // a 24-bit depth buffer

// Faces turned from the light (or edge-on to it) are dark by shading whatever a map says: only
// pixels of receivers that face the light are judged.
constexpr float kMinFacing = 1e-3f;

bool receives(const Scene& scene, const ReferenceImage& ref, size_t i) {
    return ref.visible[i] && scene.objects[ref.object[i]].receives && ref.facing[i] > kMinFacing;
}

// The neighbour one pixel along (dx, dy), or the one on the other side when that is off the
// object; its offset sign tells which was used. -1 when neither lies on the same object.
long neighbour(const ReferenceImage& ref, int x, int y, int dx, int dy, double& sign) {
    const size_t i = size_t(y) * ref.width + x;
    for (int s : {1, -1}) {
        const int nx = x + s * dx, ny = y + s * dy;
        if (nx < 0 || ny < 0 || nx >= ref.width || ny >= ref.height) continue;
        const size_t n = size_t(ny) * ref.width + nx;
        if (ref.visible[n] && ref.object[n] == ref.object[i]) {
            sign = s;
            return long(n);
        }
    }
    return -1;
}

// Where the eye's ray through `seen` meets the plane through p with normal n.
glm::dvec3 along_ray_onto_plane(const glm::dvec3& eye, const glm::dvec3& seen, const glm::dvec3& p,
                                const glm::dvec3& n) {
    const glm::dvec3 ray = seen - eye;
    return eye + ray * (glm::dot(n, p - eye) / glm::dot(n, ray));
}

// Lloyd's m at one pixel and its two factors (0 where not measured).
struct PixelAliasing {
    double m = 0.0, perspective = 0.0, projection = 0.0;
};

// A map's (u, v) is constant along a light ray and a pixel along a view ray, so on a surface T
// through p, J = d(u, v)/d(pixel) = A_l · M_T · A_e⁻¹: A_e takes the plane across the view ray (E)
// to pixels, A_l the plane across the light (L) to (u, v), and M_T slides a point of E along its
// view ray onto T, then along the light onto L (det M_T = cos φ_light / cos φ_eye). When T's normal
// lies in the plane of the two rays (Lloyd's setting), M_T keeps the direction across both rays
// and scales the other by cos φ_light / cos φ_eye. On the plane H whose normal is halfway between
// the eye and the light the two cosines are equal, so M_H is an isometry and the measure of J_H is
// the texel (A_l) against the pixel (A_e) alone: the perspective factor; the measure on T over it
// is the projection factor. Both use the same one-pixel steps: H's are the neighbours' view rays
// met with H, so that a surface which is H has a projection factor of exactly 1.
PixelAliasing pixel_aliasing(const Scene& scene, const ReferenceImage& ref, const ShadowMap& map, double texels,
                             int x, int y) {
    double sx = 1, sy = 1;
    const long right = neighbour(ref, x, y, 1, 0, sx), down = neighbour(ref, x, y, 0, 1, sy);
    if (right < 0 || down < 0) return {};
    const glm::dvec3& p = ref.position[size_t(y) * ref.width + x];
    const glm::dvec2 uv(world_to_uvz(map, p));
    if (!(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1)) return {};  // off the map: lit, no texels
    // The measure with the neighbours' points moved to `right_at` and `down_at`.
    auto texel_extent = [&](const glm::dvec3& right_at, const glm::dvec3& down_at) {
        const glm::dvec2 du = sx * (glm::dvec2(world_to_uvz(map, right_at)) - uv);
        const glm::dvec2 dv = sy * (glm::dvec2(world_to_uvz(map, down_at)) - uv);
        const double extent = texel_extent_in_pixels(uv, uv + du, uv + dv, texels);
        return std::isfinite(extent) ? extent : 0.0;
    };
    const double m = texel_extent(ref.position[right], ref.position[down]);
    if (m <= 0.0) return {};
    const glm::dvec3 eye = scene.camera.position;
    const glm::dvec3 halfway = glm::normalize(glm::normalize(eye - p) - along_light(scene.light, p));
    const double perspective = texel_extent(along_ray_onto_plane(eye, ref.position[right], p, halfway),
                                            along_ray_onto_plane(eye, ref.position[down], p, halfway));
    if (perspective <= 0.0) return {m, 0.0, 0.0};
    return {m, perspective, m / perspective};
}

ShadowError unjudged(const ReferenceImage& ref) {
    ShadowError e;
    const size_t pixels = size_t(ref.width) * ref.height;
    e.m_image.assign(pixels, 0.0f);
    e.m_perspective_image.assign(pixels, 0.0f);
    e.m_projection_image.assign(pixels, 0.0f);
    e.verdicts.assign(pixels, PixelVerdict::none);
    return e;
}

// One receiver pixel's verdict against the reference.
void judge(ShadowError& e, const ReferenceImage& ref, size_t i, bool shadowed) {
    ++e.receiver_pixels;
    e.verdicts[i] = shadowed == !ref.lit[i] ? PixelVerdict::agree
                    : shadowed             ? PixelVerdict::false_shadow
                                           : PixelVerdict::false_light;
}

// The shares of the receiver pixels judged wrong, each way.
void tally(ShadowError& e) {
    size_t false_shadow = 0, false_light = 0;
    for (PixelVerdict v : e.verdicts) {
        false_shadow += v == PixelVerdict::false_shadow;
        false_light += v == PixelVerdict::false_light;
    }
    const double n = std::max<size_t>(e.receiver_pixels, 1);
    e.false_shadow = false_shadow / n;
    e.false_light = false_light / n;
    e.misclassified = e.false_shadow + e.false_light;
}

}  // namespace

AliasingStats statistics(std::vector<double> values) {
    AliasingStats s;
    if (values.empty()) return s;
    std::sort(values.begin(), values.end());
    s.max = values.back();
    for (double v : values) s.mean += v / double(values.size());
    s.p95 = values[std::min(values.size() - 1, size_t(0.95 * double(values.size())))];
    return s;
}

ShadowError measure_shadow_error(const Scene& scene, const ReferenceImage& ref, const DepthMap& depth,
                                 const ShadowSetup& setup, double bias) {
    ShadowError e = unjudged(ref);
    std::vector<double> ms, perspectives, projections, depth_steps;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const size_t i = size_t(y) * ref.width + x;
            if (!receives(scene, ref, i)) continue;
            const glm::dvec3& p = ref.position[i];
            const int which = select_map(setup, p);
            if (which < 0) {  // no map for this point: lit
                judge(e, ref, i, false);
                continue;
            }
            const ShadowMap& map = setup.maps[which];
            const double texels = tile_resolution(map, depth.resolution);
            judge(e, ref, i, in_shadow(depth, setup, p, bias_at(setup, depth.resolution, scene.light, p, ref.facing[i], bias)));
            if (const double step = world_per_depth_unit(map, along_light(scene.light, p), p) / kDepthBufferSteps;
                std::isfinite(step))
                depth_steps.push_back(step);
            const PixelAliasing a = pixel_aliasing(scene, ref, map, texels, x, y);
            if (a.m > 0.0) {
                e.m_image[i] = float(a.m);
                ms.push_back(a.m);
            }
            if (a.perspective > 0.0) {
                e.m_perspective_image[i] = float(a.perspective);
                e.m_projection_image[i] = float(a.projection);
                perspectives.push_back(a.perspective);
                projections.push_back(a.projection);
            }
        }
    tally(e);
    e.m = statistics(std::move(ms));
    e.m_perspective = statistics(std::move(perspectives));
    e.m_projection = statistics(std::move(projections));
    e.depth_step = statistics(std::move(depth_steps));
    return e;
}

ShadowError judge_shadows(const Scene& scene, const ReferenceImage& ref, const std::vector<uint8_t>& shadowed) {
    ShadowError e = unjudged(ref);
    for (size_t i = 0; i < shadowed.size(); ++i)
        if (receives(scene, ref, i)) judge(e, ref, i, shadowed[i] != 0);
    tally(e);
    return e;
}

}  // namespace shadowlab
