#include "metrics/map_breakdown.hpp"

#include <algorithm>

namespace shadowlab {
namespace {

constexpr int kNoMap = -1;

// The map each receiver pixel reads (kNoMap elsewhere).
std::vector<int> map_per_pixel(const ReferenceImage& ref, const ShadowError& e, const ShadowSetup& setup) {
    std::vector<int> map(e.verdicts.size(), kNoMap);
    for (size_t i = 0; i < map.size(); ++i)
        if (e.verdicts[i] != PixelVerdict::none) map[i] = select_map(setup, ref.position[i]);
    return map;
}

// 1 where a receiver pixel borders (4-neighbours) a receiver pixel of another map.
std::vector<uint8_t> boundaries(const std::vector<int>& map, int width, int height) {
    std::vector<uint8_t> at(map.size(), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * width + x;
            if (map[i] == kNoMap) continue;
            auto differs = [&](int nx, int ny) {
                if (nx < 0 || ny < 0 || nx >= width || ny >= height) return false;
                const int other = map[size_t(ny) * width + nx];
                return other != kNoMap && other != map[i];
            };
            at[i] = differs(x + 1, y) || differs(x - 1, y) || differs(x, y + 1) || differs(x, y - 1);
        }
    return at;
}

// Grown by `radius` pixels in every direction (a square: rows, then columns).
std::vector<uint8_t> dilated(std::vector<uint8_t> mask, int width, int height, int radius) {
    std::vector<uint8_t> rows(mask.size(), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int dx = -radius; dx <= radius && !rows[size_t(y) * width + x]; ++dx)
                if (x + dx >= 0 && x + dx < width) rows[size_t(y) * width + x] = mask[size_t(y) * width + x + dx];
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            uint8_t& out = mask[size_t(y) * width + x];
            out = 0;
            for (int dy = -radius; dy <= radius && !out; ++dy)
                if (y + dy >= 0 && y + dy < height) out = rows[size_t(y + dy) * width + x];
        }
    return mask;
}

bool misclassified(PixelVerdict v) { return v == PixelVerdict::false_shadow || v == PixelVerdict::false_light; }

}  // namespace

MapBreakdown break_down_by_map(const ReferenceImage& ref, const ShadowError& e, const ShadowSetup& setup,
                               int seam_pixels) {
    const std::vector<int> map = map_per_pixel(ref, e, setup);
    const std::vector<uint8_t> near_seam =
        dilated(boundaries(map, ref.width, ref.height), ref.width, ref.height, seam_pixels);
    MapBreakdown out;
    out.maps.resize(setup.maps.size());
    std::vector<std::vector<double>> perspective(setup.maps.size());
    for (size_t i = 0; i < map.size(); ++i) {
        if (map[i] == kNoMap) continue;
        MapShare& share = out.maps[map[i]];
        ++share.pixels;
        if (e.m_perspective_image[i] > 0.0f) perspective[map[i]].push_back(e.m_perspective_image[i]);
        if (!misclassified(e.verdicts[i])) continue;
        ++share.misclassified;
        ++out.misclassified;
        out.near_seams += near_seam[i];
    }
    for (size_t k = 0; k < out.maps.size(); ++k) out.maps[k].m_perspective = statistics(std::move(perspective[k]));
    return out;
}

}  // namespace shadowlab
