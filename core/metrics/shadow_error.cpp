#include "metrics/shadow_error.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "lookup/depth_bias.hpp"
#include "math/parallel_rows.hpp"
#include "math/singular_values.hpp"
#include "metrics/pixel_evidence.hpp"
#include "metrics/pixel_steps.hpp"
#include "reference/camera_depth_image.hpp"

namespace shadowlab {

double texel_extent_in_pixels(const glm::dvec2& uv, const glm::dvec2& uv_right, const glm::dvec2& uv_down,
                              double resolution) {
    const double sigma_min = smallest_singular_value(glm::dmat2(uv_right - uv, uv_down - uv));  // per pixel right, down
    return sigma_min > 0.0 ? 1.0 / (resolution * sigma_min) : INFINITY;
}

namespace {

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
PixelAliasing pixel_aliasing(const ShadowMap& map, double texels, const PixelSteps& steps) {
    const glm::dvec2 uv(world_to_uvz(map, steps.point));
    if (!(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1)) return {};  // off the map: lit, no texels
    // The measure with the neighbours' points moved to `right_at` and `down_at`.
    auto texel_extent = [&](const glm::dvec3& right_at, const glm::dvec3& down_at) {
        const glm::dvec2 du = steps.right_sign * (glm::dvec2(world_to_uvz(map, right_at)) - uv);
        const glm::dvec2 dv = steps.down_sign * (glm::dvec2(world_to_uvz(map, down_at)) - uv);
        const double extent = texel_extent_in_pixels(uv, uv + du, uv + dv, texels);
        return std::isfinite(extent) ? extent : 0.0;
    };
    const double m = texel_extent(steps.right, steps.down);
    if (m <= 0.0) return {};
    const double perspective = texel_extent(steps.right_on_halfway, steps.down_on_halfway);
    if (perspective <= 0.0) return {m, 0.0, 0.0};
    return {m, perspective, m / perspective};
}

// The world distance along the light that one step of the map's depth format stands for at p: the
// format's step at p's depth (raster/depth_format.hpp) in world units per unit of depth.
double world_depth_step(const ShadowMap& map, const DepthFormat& format, const glm::dvec3& l, const glm::dvec3& p) {
    return world_per_depth_unit(map, l, p) * depth_step(format, world_to_uvz(map, p).z);
}

ShadowError unjudged(const ReferenceImage& ref) {
    ShadowError e;
    const size_t pixels = size_t(ref.width) * ref.height;
    e.m_image.assign(pixels, 0.0f);
    e.m_perspective_image.assign(pixels, 0.0f);
    e.m_projection_image.assign(pixels, 0.0f);
    e.verdicts.assign(pixels, PixelVerdict::none);
    e.causes.assign(pixels, PixelCause::none);
    return e;
}

// One receiver pixel's verdict against the reference.
void judge(ShadowError& e, const ReferenceImage& ref, size_t i, bool shadowed) {
    ++e.receiver_pixels;
    e.verdicts[i] = shadowed == !ref.lit[i] ? PixelVerdict::agree
                    : shadowed              ? PixelVerdict::false_shadow
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

std::vector<float> receiver_visibility(const Scene& scene, const ReferenceImage& ref, const ShadowReader& reader,
                                       LookupCount* count) {
    std::vector<float> visibility(ref.visible.size(), -1.0f);
    std::vector<LookupCount> counts(row_threads());  // one per thread
    const ContactShadow& contact = reader.lookup().contact;
    const std::optional<CameraDepthImage> depths =
        contact.on() ? std::optional(camera_depth_image(scene.camera, ref)) : std::nullopt;
    parallel_rows([&](int first, int stride) {
        for (int y = first; y < ref.height; y += stride)
            for (int x = 0; x < ref.width; ++x)
                if (const size_t i = size_t(y) * ref.width + x; receives(scene, ref, i)) {
                    const Receiver r{
                        .position = ref.position[i], .normal = ref.normal[i], .rotation = pixel_rotation(x, y)};
                    const double v = reader.visibility(r, &counts[first]);
                    visibility[i] =
                        float(depths ? with_contact_shadow(v, contact, *depths, scene.light, r.position) : v);
                }
    });
    if (count)
        for (const LookupCount& c : counts) {
            count->lookups += c.lookups;
            count->taps += c.taps;
            count->searches_clamped += c.searches_clamped;
        }
    return visibility;
}

ShadowError measure_shadow_error(const Scene& scene, const ReferenceImage& ref, const ShadowReader& reader,
                                 const std::vector<float>& visibility) {
    ShadowError e = unjudged(ref);
    const ShadowSetup& setup = reader.setup();
    std::vector<double> ms, perspectives, projections, depth_steps;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const size_t i = size_t(y) * ref.width + x;
            if (!receives(scene, ref, i)) continue;
            judge(e, ref, i, visibility[i] < 0.5f);
            const glm::dvec3& p = ref.position[i];
            const int which = select_map(setup, p);
            if (which < 0) continue;  // no map for this point: lit, no texels
            const ShadowMap& map = setup.maps[which];
            if (const double step = world_depth_step(map, reader.depth().format, along_light(scene.light, p), p);
                std::isfinite(step))
                depth_steps.push_back(step);
            const std::optional<PixelSteps> steps = pixel_steps(scene, ref, x, y);
            if (!steps) continue;
            const PixelAliasing a = pixel_aliasing(map, tile_resolution(map, reader.depth().resolution), *steps);
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
    e.visibility = visibility_error(ref, visibility);
    e.causes = diagnose_pixels(ref, reader, e);
    return e;
}

ShadowError judge_shadows(const Scene& scene, const ReferenceImage& ref, const std::vector<uint8_t>& shadowed) {
    ShadowError e = unjudged(ref);
    std::vector<float> visibility(shadowed.size(), -1.0f);
    for (size_t i = 0; i < shadowed.size(); ++i)
        if (receives(scene, ref, i)) {
            judge(e, ref, i, shadowed[i] != 0);
            visibility[i] = shadowed[i] ? 0.0f : 1.0f;
        }
    tally(e);
    e.visibility = visibility_error(ref, std::move(visibility));
    e.causes = diagnose_technique(e);
    return e;
}

}  // namespace shadowlab
