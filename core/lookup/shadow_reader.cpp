#include "lookup/shadow_reader.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "maps/map_lookup.hpp"
#include "math/stopwatch.hpp"

namespace shadowlab {
namespace {

glm::dvec3 along_light(const Light& light, const glm::dvec3& p) {
    return light.is_directional() ? light.direction : glm::normalize(p - light.position);
}

// The centre of a texture texel in a map's (u, v).
glm::dvec2 texel_centre_uv(const ShadowMap& map, const glm::ivec2& texel, int resolution) {
    const glm::dvec2 t = (glm::dvec2(texel) + 0.5) / double(resolution);
    const glm::dvec2 lo(map.viewport.x, map.viewport.y), hi(map.viewport.z, map.viewport.w);
    return (t - lo) / (hi - lo);
}

// The map's depth of p moved `bias` world units back toward the light; -inf (lit by any texel) when
// the bias reaches the light or its map's centre.
double biased_depth(const ShadowMap& map, const glm::dvec3& p, const glm::dvec3& l, double bias) {
    const glm::dvec4 h = map_homogeneous(map, p - bias * l);
    return h.w > 0.0 && hemisphere_side(map, p - bias * l) >= 0.0 ? h.z / h.w : -INFINITY;
}

}  // namespace

ShadowReader::ShadowReader(const ShadowSetup& setup, const DepthMap& depth, const Light& light,
                           const ShadowLookup& lookup)
    : setup_(setup),
      depth_(depth),
      light_(light),
      lookup_(lookup),
      filter_(&filter_of(lookup.filter)),
      taps_(filter_->taps(lookup.filter)) {
    const ShadowFilter& f = lookup.filter;
    if (filter_->moments.of_depth) {
        const Stopwatch watch;
        moments_ = blurred_moments(depth, setup, f);
        prefilter_ms_ = watch.ms();
    }
}

std::vector<Note> ShadowReader::fallbacks(const LookupCount& count) const {
    return filter_->fallbacks ? filter_->fallbacks(*this, count) : std::vector<Note>{};
}

double ShadowReader::visibility(const Receiver& r, LookupCount* count) const {
    const MapBlend blend = blend_of(setup_, r.position);
    if (blend.map < 0) return 1.0;
    if (blend.next < 0) return map_visibility(blend.map, r, count);
    return (1.0 - blend.weight) * map_visibility(blend.map, r, count) +
           blend.weight * map_visibility(blend.next, r, count);
}

// The receiver under one map, biased: the normal offset moves the point, then the constant and
// slope-scaled biases (world lengths) move it nearer the light along the light ray for its depth
// alone: the biased depth is the map's depth of p − b l, exact whatever the map's perspective.
std::optional<MapReceiver> ShadowReader::under(int which, const Receiver& r) const {
    const ShadowMap& map = setup_.maps[which];
    const DepthBias& bias = lookup_.bias;
    const double texels = tile_resolution(map, depth_.resolution);
    const glm::dvec3 l = along_light(light_, r.position);
    const double texel_world = texel_world_size(map, texels, l, r.position);
    const glm::dvec3 p = r.position + r.normal * finite_or(bias.normal_offset * texel_world, 0.0);
    const std::optional<MapLookup> at = look_up_in(setup_, which, p, 0.0);
    if (!at) return std::nullopt;
    const double slope_scaled =
        bias.slope_scale > 0.0 ? bias.slope_scale * slope_scaled_bias(texel_world, glm::dot(r.normal, -l)) : 0.0;
    return MapReceiver{
        .map = map,
        .index = which,
        .position = p,
        .light_direction = l,
        .texels = texels,
        .uv = at->uv,
        .depth = biased_depth(map, p, l, bias.constant + finite_or(slope_scaled, 0.0)),
        .plane_gradient = bias.receiver_plane ? receiver_plane_gradient(map, p, r.normal) : glm::dvec2(0.0),
        .texel_world = texel_world};
}

double ShadowReader::map_visibility(int which, const Receiver& r, LookupCount* count) const {
    const std::optional<MapReceiver> m = under(which, r);
    if (!m) return 1.0;
    if (count) ++count->lookups;
    return filter_->visibility(*this, *m, r, count);
}

std::optional<TexelRead> ShadowReader::read_texel(int which, const Receiver& r) const {
    const std::optional<MapReceiver> m = under(which, r);
    if (!m) return std::nullopt;
    const glm::ivec2 texel = texel_of(m->map, m->uv, depth_.resolution);
    const glm::dvec2 centre = texel_centre_uv(m->map, texel, depth_.resolution);
    return TexelRead{.texel = texel,
                     .texel_centre_uv = centre,
                     .stored = depth_.at(texel.x, texel.y),
                     .receiver = m->depth + glm::dot(m->plane_gradient, centre - m->uv)};
}

TapTexel ShadowReader::tap_texel(const MapReceiver& m, const glm::dvec2& uv) const {
    const PageTable& pages = setup_.selection.pages;  // empty but for a virtual map: one test per tap
    if (const std::optional<PageAcross> across = pages.pages.empty() ? std::nullopt : page_across(pages, m.index, uv)) {
        const ShadowMap& there = setup_.maps[across->map];
        const glm::ivec2 texel = texel_of(there, across->uv, depth_.resolution);
        return {texel, texel_centre_uv(there, texel, depth_.resolution) + glm::dvec2(across->offset)};
    }
    const glm::ivec2 texel = texel_of(m.map, uv, depth_.resolution);
    return {texel, texel_centre_uv(m.map, texel, depth_.resolution)};
}

// The weighted share of taps the receiver passes: each reads its nearest texel (tap_texel)
// and compares the receiver's depth there, on its plane when the receiver-plane bias is on.
double ShadowReader::lit_share(const MapReceiver& m, const std::vector<KernelTap>& taps, double radius_texels,
                               double rotation, LookupCount* count) const {
    const double c = std::cos(rotation), s = std::sin(rotation);
    double lit = 0.0;
    for (const KernelTap& tap : taps) {
        const glm::dvec2 uv = m.uv + rotated(tap.offset, c, s) * (radius_texels / m.texels);
        const TapTexel read = tap_texel(m, uv);
        const double receiver = m.depth + glm::dot(m.plane_gradient, read.centre_uv - m.uv);
        if (receiver <= depth_.at(read.texel.x, read.texel.y)) lit += tap.weight;
    }
    if (count) count->taps += taps.size();
    return std::min(lit, 1.0);  // the weights' rounding
}

}  // namespace shadowlab
