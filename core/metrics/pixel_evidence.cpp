#include "metrics/pixel_evidence.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "lookup/depth_bias.hpp"
#include "maps/map_lookup.hpp"
#include "raster/depth_format.hpp"
#include "metrics/map_breakdown.hpp"

namespace shadowlab {
namespace {

// Depths (in [0, 1]) that differ by less than this are one: the rounding of the visible points
// (float rays) and of the raster's plane equations, far below any format's step.
constexpr double kDepthNoise = 1e-12;

bool misclassified(PixelVerdict v) { return v == PixelVerdict::false_shadow || v == PixelVerdict::false_light; }
bool shadowed_by(const TexelRead& read) { return read.receiver > read.stored; }

// The same reader's maps read three ways: as the run reads them (filter and biases), hard with the
// run's biases, and hard with none.
class EvidenceGatherer {
public:
    EvidenceGatherer(const ReferenceImage& ref, const ShadowReader& reader, const ShadowError& e)
        : ref_(ref),
          reader_(reader),
          error_(e),
          hard_(reader.setup(), reader.depth(), reader.light(), hard_lookup(reader.lookup(), reader.lookup().bias)),
          unbiased_(reader.setup(), reader.depth(), reader.light(),
                    hard_lookup(reader.lookup(), DepthBias{.slope_scale = 0.0})) {}

    PixelEvidence gather(int x, int y) const {
        const size_t i = size_t(y) * ref_.width + x;
        const Receiver r{.position = ref_.position[i], .normal = ref_.normal[i], .rotation = pixel_rotation(x, y)};
        PixelEvidence e{.false_shadow = error_.verdicts[i] == PixelVerdict::false_shadow};
        e.contact_darkened = e.false_shadow && reader_.lookup().contact.on() && reader_.visibility(r) >= 0.5;
        if (e.contact_darkened) return e;
        const MapBlend blend = blend_of(reader_.setup(), r.position);
        const std::optional<TexelRead> read = blend.map < 0 ? std::nullopt : hard_.read_texel(blend.map, r);
        if (!read || !within_depth_range(blend.map, r.position)) {
            e.reads_map = false;
            return e;
        }
        const bool truly_lit = ref_.lit[i] != 0;
        e.filtered = reader_.lookup().filter.soft();
        e.hard_right = e.filtered && (hard_.visibility(r) >= 0.5) == truly_lit;  // read only when it can decide
        e.seam = in_disagreeing_band(blend, r) || beside_a_later_map_reading_right(blend.map, r, x, y, truly_lit);
        e.gap = read->receiver - read->stored;
        e.step = depth_step(reader_.depth().format, read->stored);
        const ReceiverPlane plane = receiver_plane(blend.map, r);
        e.own_surface = read->stored >= plane.depth_at(read->texel_centre_uv) - plane.tolerance(e.step);
        if (const std::optional<TexelRead> bare = unbiased_.read_texel(blend.map, r))
            e.unbiased_occluder = bare->stored < plane.depth_at(bare->texel_centre_uv) - plane.tolerance(e.step) &&
                                  bare->stored < plane.depth - e.step;
        e.straddles_edge = e.false_shadow ? !e.own_surface : lit_within_footprint(x, y);
        e.projection_dominant = error_.m_projection_image[i] > std::max(error_.m_perspective_image[i], 1.0f);
        return e;
    }

private:
    static ShadowLookup hard_lookup(ShadowLookup lookup, const DepthBias& bias) {
        lookup.filter = ShadowFilter{};
        lookup.bias = bias;
        return lookup;
    }

    // The receiver's tangent plane in the map: its depth at a texel centre, and how far the stored
    // depth may lie in front of it and still be this surface: a quarter of the plane's depth change
    // across a texel, two format steps, and kDepthNoise.
    struct ReceiverPlane {
        glm::dvec2 uv;
        double depth;
        glm::dvec2 gradient;
        double texels;
        double depth_at(const glm::dvec2& at) const { return depth + glm::dot(gradient, at - uv); }
        double tolerance(double step) const {
            return 0.25 * (std::abs(gradient.x) + std::abs(gradient.y)) / texels + 2.0 * step + kDepthNoise;
        }
    };
    ReceiverPlane receiver_plane(int map, const Receiver& r) const {
        const ShadowMap& m = reader_.setup().maps[map];
        const glm::dvec3 uvz = world_to_uvz(m, r.position);
        return {.uv = glm::dvec2(uvz),
                .depth = uvz.z,
                .gradient = receiver_plane_gradient(m, r.position, r.normal),
                .texels = tile_resolution(m, reader_.depth().resolution)};
    }

    // Between the map's near and far planes: a point before the near plane reads lit whatever is
    // stored, one past the far plane reads shadowed.
    bool within_depth_range(int map, const glm::dvec3& p) const {
        const double d = world_to_uvz(reader_.setup().maps[map], p).z;
        return d >= 0.0 && d <= 1.0;
    }

    bool in_disagreeing_band(const MapBlend& blend, const Receiver& r) const {
        if (blend.next < 0) return false;
        const std::optional<TexelRead> a = hard_.read_texel(blend.map, r), b = hard_.read_texel(blend.next, r);
        return a && b && shadowed_by(*a) != shadowed_by(*b);
    }

    // A map after this one (cascades: the next coarser; an atlas: one the selection tries later)
    // serves a pixel of the same object within kSeamPixels, and it reads this point right: this map
    // is wrong where its coverage ends. (Beside a finer map, a coarser one's error is its own
    // texels'; across an object's outline the next map serves another surface, not this one's.)
    bool beside_a_later_map_reading_right(int own, const Receiver& r, int x, int y, bool truly_lit) const {
        if (reader_.setup().maps.size() < 2) return false;
        const size_t i = size_t(y) * ref_.width + x;
        std::set<int> others;
        for (int dy = -kSeamPixels; dy <= kSeamPixels; ++dy)
            for (int dx = -kSeamPixels; dx <= kSeamPixels; ++dx)
                if (const long n = pixel(x + dx, y + dy); n >= 0 && ref_.object[size_t(n)] == ref_.object[i])
                    if (const int m = select_map(reader_.setup(), ref_.position[size_t(n)]); m > own) others.insert(m);
        return std::any_of(others.begin(), others.end(), [&](int m) {
            const std::optional<TexelRead> read = hard_.read_texel(m, r);
            return read && shadowed_by(*read) != truly_lit;
        });
    }

    // A lit reference pixel of the same object within the texel's extent in the image (m pixels,
    // at least one, at most 16): the shadow's true edge passes through the texel.
    bool lit_within_footprint(int x, int y) const {
        const size_t i = size_t(y) * ref_.width + x;
        const int reach = std::clamp(int(std::ceil(error_.m_image[i])), 1, 16);
        for (int dy = -reach; dy <= reach; ++dy)
            for (int dx = -reach; dx <= reach; ++dx)
                if (const long n = pixel(x + dx, y + dy);
                    n >= 0 && ref_.lit[size_t(n)] && ref_.object[size_t(n)] == ref_.object[i])
                    return true;
        return false;
    }

    long pixel(int x, int y) const {
        return x < 0 || y < 0 || x >= ref_.width || y >= ref_.height ? -1 : long(y) * ref_.width + x;
    }

    const ReferenceImage& ref_;
    const ShadowReader& reader_;
    const ShadowError& error_;
    const ShadowReader hard_, unbiased_;
};

}  // namespace

std::vector<PixelCause> diagnose_pixels(const ReferenceImage& ref, const ShadowReader& reader,
                                        const ShadowError& error) {
    std::vector<PixelCause> causes(error.verdicts.size(), PixelCause::none);
    const EvidenceGatherer gatherer(ref, reader, error);
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x)
            if (const size_t i = size_t(y) * ref.width + x; misclassified(error.verdicts[i]))
                causes[i] = cause_of(gatherer.gather(x, y));
    return causes;
}

PixelEvidence evidence_of(const ReferenceImage& ref, const ShadowReader& reader, const ShadowError& error, int x,
                          int y) {
    return EvidenceGatherer(ref, reader, error).gather(x, y);
}

std::vector<PixelCause> diagnose_technique(const ShadowError& error) {
    std::vector<PixelCause> causes(error.verdicts.size(), PixelCause::none);
    for (size_t i = 0; i < causes.size(); ++i)
        if (misclassified(error.verdicts[i])) causes[i] = PixelCause::technique;
    return causes;
}

}  // namespace shadowlab
