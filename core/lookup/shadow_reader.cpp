#include "lookup/shadow_reader.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "lookup/chebyshev.hpp"
#include "lookup/pcss.hpp"
#include "maps/map_lookup.hpp"
#include "math/stopwatch.hpp"

namespace shadowlab {

struct ShadowReader::MapReceiver {
    const ShadowMap& map;
    glm::dvec3 position;         // the point looked up: the receiver, moved by the normal offset
    glm::dvec3 light_direction;  // the way light travels there
    double texels;               // across the map's tile
    glm::dvec2 uv;
    double depth;               // the point's depth, less the bias in depth units
    glm::dvec2 plane_gradient;  // receiver plane: ∂d/∂(u, v); 0 when off
    double texel_world;         // a texel's world width across the light there
};

namespace {

glm::dvec3 along_light(const Light& light, const glm::dvec3& p) {
    return light.is_directional() ? light.direction : glm::normalize(p - light.position);
}

glm::dvec2 rotated(const glm::dvec2& v, double c, double s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }

// The centre of a texture texel in a map's (u, v).
glm::dvec2 texel_centre_uv(const ShadowMap& map, const glm::ivec2& texel, int resolution) {
    const glm::dvec2 t = (glm::dvec2(texel) + 0.5) / double(resolution);
    const glm::dvec2 lo(map.viewport.x, map.viewport.y), hi(map.viewport.z, map.viewport.w);
    return (t - lo) / (hi - lo);
}

double finite_or(double value, double otherwise) { return std::isfinite(value) ? value : otherwise; }

// The map's depth of p moved `bias` world units back toward the light; -inf (lit by any texel) when
// the bias reaches the light or its map's centre.
double biased_depth(const ShadowMap& map, const glm::dvec3& p, const glm::dvec3& l, double bias) {
    const glm::dvec4 h = map_homogeneous(map, p - bias * l);
    return h.w > 0.0 && hemisphere_side(map, p - bias * l) >= 0.0 ? h.z / h.w : -INFINITY;
}

}  // namespace

ShadowReader::ShadowReader(const ShadowSetup& setup, const DepthMap& depth, const Light& light,
                           const ShadowLookup& lookup)
    : setup_(setup), depth_(depth), light_(light), lookup_(lookup), taps_(filter_taps(lookup.filter)) {
    const ShadowFilter& f = lookup.filter;
    if (f.reads_moments()) {
        const Stopwatch watch;
        moments_ = blurred_moments(depth, setup, f);
        prefilter_ms_ = watch.ms();
    }
}

std::vector<Note> ShadowReader::fallbacks(const LookupCount& count) const {
    std::vector<Note> notes;
    if (lookup_.filter.kind != FilterKind::pcss) return notes;
    if (!light_.is_area())
        notes.push_back({NoteKind::light_without_size, "set the light's radius or angular_radius_deg"});
    if (count.searches_clamped > 0)
        notes.push_back({NoteKind::search_clamped, std::to_string(count.searches_clamped) + " of " +
                                                       std::to_string(count.lookups) + " lookups, at " +
                                                       std::to_string(int(kMaxSearchTexels)) + " texels"});
    return notes;
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
std::optional<ShadowReader::MapReceiver> ShadowReader::under(int which, const Receiver& r) const {
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
    const ShadowFilter& f = lookup_.filter;
    switch (f.kind) {
        case FilterKind::hard: return lit_share(*m, taps_, 0.0, 0.0, count);
        case FilterKind::pcf: {
            const double radius = f.radius_world > 0.0 ? f.radius_world / m->texel_world : f.radius_texels;
            return lit_share(*m, taps_, finite_or(radius, 0.0), f.kernel == PcfKernel::poisson ? r.rotation : 0.0,
                             count);
        }
        case FilterKind::pcss: return soft_shadow(*m, r, count);
        case FilterKind::vsm:
        case FilterKind::evsm: return chebyshev_visibility(*m, count);
    }
    return 1.0;
}

// The weighted share of taps the receiver passes: each reads its nearest texel (kept in the tile)
// and compares the receiver's depth there, on its plane when the receiver-plane bias is on.
double ShadowReader::lit_share(const MapReceiver& m, const std::vector<KernelTap>& taps, double radius_texels,
                               double rotation, LookupCount* count) const {
    const double c = std::cos(rotation), s = std::sin(rotation);
    double lit = 0.0;
    for (const KernelTap& tap : taps) {
        const glm::dvec2 uv = m.uv + rotated(tap.offset, c, s) * (radius_texels / m.texels);
        const glm::ivec2 texel = texel_of(m.map, uv, depth_.resolution);
        const double receiver =
            m.depth + glm::dot(m.plane_gradient, texel_centre_uv(m.map, texel, depth_.resolution) - m.uv);
        if (receiver <= depth_.at(texel.x, texel.y)) lit += tap.weight;
    }
    if (count) count->taps += taps.size();
    return std::min(lit, 1.0);  // the weights' rounding
}

double ShadowReader::soft_shadow(const MapReceiver& m, const Receiver& r, LookupCount* count) const {
    // PCSS step 1: the blocker search, over the footprint of the light seen from the receiver as far
    // back as the map's near plane (d = 0), at most kMaxSearchTexels.
    const double to_near_plane = distance_back_to_depth(m.map, m.light_direction, m.position, 0.0);
    double search = blocker_search_radius(light_, m.position, to_near_plane) / m.texel_world;
    if (!(search <= kMaxSearchTexels)) {
        search = kMaxSearchTexels;
        if (count) ++count->searches_clamped;
    }
    const double c = std::cos(r.rotation), s = std::sin(r.rotation);
    double blocker_depth = 0.0;
    int blockers = 0;
    for (const KernelTap& tap : taps_) {
        const glm::ivec2 texel =
            texel_of(m.map, m.uv + rotated(tap.offset, c, s) * (search / m.texels), depth_.resolution);
        const double stored = depth_.at(texel.x, texel.y);
        if (stored < m.depth) blocker_depth += stored, ++blockers;
    }
    if (count) count->taps += taps_.size();
    if (blockers == 0) return 1.0;  // nothing between the receiver and the light
    blocker_depth /= blockers;
    // PCSS step 2: the penumbra the average blocker casts, w = (d_r − d_b) w_light / d_b.
    const double blocker_distance = distance_back_to_depth(m.map, m.light_direction, m.position, blocker_depth);
    const double radius = penumbra_width(light_, m.position, blocker_distance) / 2.0 / m.texel_world;
    // PCSS step 3: PCF over that penumbra (never wider than the search that found its blockers).
    return lit_share(m, taps_, std::min(finite_or(radius, search), search), r.rotation, count);
}

// VSM and EVSM: Chebyshev's bound on the prefiltered moments at the receiver's depth. EVSM's floor
// on the variance scales with the warp's slope, (c e^{cd})², so that it is the same in depth units.
double ShadowReader::chebyshev_visibility(const MapReceiver& m, LookupCount* count) const {
    const ShadowFilter& f = lookup_.filter;
    const glm::dvec4 mo = sample_moments(*moments_, m.map, m.uv);
    if (count) count->taps += 4;
    double p = 0.0;
    if (f.kind == FilterKind::vsm) {
        p = chebyshev_upper_bound(mo.x, std::max(mo.y - mo.x * mo.x, f.min_variance), m.depth);
    } else {
        const double positive = evsm_positive_warp(m.depth, f.evsm_positive);
        const double negative = evsm_negative_warp(m.depth, f.evsm_negative);
        const double floor_positive = f.min_variance * std::pow(f.evsm_positive * positive, 2);
        const double floor_negative = f.min_variance * std::pow(f.evsm_negative * negative, 2);
        p = std::min(chebyshev_upper_bound(mo.x, std::max(mo.y - mo.x * mo.x, floor_positive), positive),
                     chebyshev_upper_bound(mo.z, std::max(mo.w - mo.z * mo.z, floor_negative), negative));
    }
    return reduce_light_bleeding(p, f.bleed_reduction);
}

}  // namespace shadowlab
