#pragma once
// How wrong a shadow map is against the exact reference, pixel by pixel of the camera image.
#include <cstdint>
#include <vector>

#include "maps/map_lookup.hpp"
#include "lookup/shadow_reader.hpp"
#include "metrics/pixel_cause.hpp"
#include "metrics/visibility_error.hpp"
#include "raster/depth_map.hpp"
#include "reference/exact_shadows.hpp"

namespace shadowlab {

enum class PixelVerdict : uint8_t { none, agree, false_shadow, false_light };

struct AliasingStats {
    double max = 0.0, mean = 0.0, p95 = 0.0;
};
AliasingStats statistics(std::vector<double> values);  // all zero for none

struct ShadowError {
    size_t receiver_pixels = 0;  // visible pixels of objects that receive shadows, on faces turned to the light
    // Shares of receiver pixels: false shadow (acne: the map shadows a lit point) and false light
    // (leaks, peter panning: the map lights a shadowed point); misclassified is their sum.
    double misclassified = 0.0, false_shadow = 0.0, false_light = 0.0;
    // Lloyd's m: the longest extent of one map texel projected into the image, in pixels. Lloyd,
    // Tuft, Yoon and Manocha (2006) split it as m = perspective × projection: a texel's width
    // across the light against a pixel's width across the view ray (perspective aliasing, which a
    // parameterization sets) times cos φ_eye / cos φ_light, φ the angles between the surface's
    // normal and the eye and the light (projection aliasing, which the surface sets). Per pixel,
    // with the same measure:
    //   m_perspective = m on the plane through the point facing halfway between the eye and the
    //                   light (normal ∝ to_eye + to_light): there cos φ_eye = cos φ_light and the
    //                   surface drops out (see pixel_aliasing in shadow_error.cpp);
    //   m_projection  = m / m_perspective: what the real surface's orientation adds. It lies
    //                   between the two stretches the surface's tilt (against the halfway plane's)
    //                   gives a texel's image, which depend on the normal, the light and the view
    //                   ray alone: 1 and Lloyd's cos φ_eye / cos φ_light where the three lie in one
    //                   plane, his ratio itself where the texel is longest in that plane (up to
    //                   the pixel footprint's slight anisotropy off the image centre). Where in
    //                   that range a pixel falls depends on the way its texel is longest, so maps
    //                   differ in it; it is 1 on a face turned to both the eye and the light, and
    //                   without bound on faces edge-on to the light.
    // m_perspective × m_projection = m at every pixel where the factors are measured. (m's 2D
    // measure does not split into a map's part and a surface's part exactly; this split keeps the
    // product and gives the map's part alone to m_perspective.)
    AliasingStats m, m_perspective, m_projection;
    // Depth resolution: the world distance along the light that one step of the map's depth format
    // (the reader's DepthMap::format: depth_step, raster/depth_format.hpp) stands for at each judged
    // pixel's depth (max, mean, 95th percentile).
    AliasingStats depth_step;
    // Per pixel; 0 where not measured.
    std::vector<float> m_image, m_perspective_image, m_projection_image;
    std::vector<PixelVerdict> verdicts;  // per pixel
    std::vector<PixelCause> causes;  // per pixel: why it is misclassified (metrics/pixel_evidence.hpp); none elsewhere
    VisibilityError visibility;      // against the reference's visibility (soft where traced)
};

// The visibility of every receiver pixel under the reader's maps (-1 elsewhere): the lookups,
// alone, so that their cost can be timed; `count` sums their taps. With the lookup's contact shadows
// on, each pixel's visibility is multiplied by its march through the reference's depth image
// (lookup/contact_shadow.hpp); off, no depth image is made.
std::vector<float> receiver_visibility(const Scene& scene, const ReferenceImage& reference, const ShadowReader& reader,
                                       LookupCount* count = nullptr);

// The reader's maps judged against the reference from those visibilities: a pixel is shadowed
// below one half. Each pixel's m counts the texels of the map the setup's selection gives it; each
// misclassified pixel gets its cause from what its lookup read.
ShadowError measure_shadow_error(const Scene& scene, const ReferenceImage& reference, const ShadowReader& reader,
                                 const std::vector<float>& visibility);

// The same judgement of a technique without texels (shadow volumes, planar projection): its
// per-pixel verdicts (1: shadowed) against the reference; m and depth_step stay 0; the cause of
// every wrong pixel is `technique`.
ShadowError judge_shadows(const Scene& scene, const ReferenceImage& reference, const std::vector<uint8_t>& shadowed);

// m at one pixel from the map coordinates of it and its neighbours one pixel right and down:
// J = d(u, v)/d(pixel); a texel (1/N wide in u and v) spans 1 / (N σ_min(J)) pixels at most.
double texel_extent_in_pixels(const glm::dvec2& uv, const glm::dvec2& uv_right, const glm::dvec2& uv_down,
                              double resolution);

}  // namespace shadowlab
