#include "lookup/moment_map.hpp"

#include <algorithm>
#include <cmath>

#include "maps/map_lookup.hpp"

namespace shadowlab {
namespace {

// One pass of the separable box blur over a tile's texels, along x (axis 0) or y (axis 1), edges
// clamped to the tile. Each window summed afresh, in double: a running sum (or prefix sums) of
// EVSM's moments, which span e^0 to e^{2c}, would lose the small ones to the large.
void blur_along(std::vector<glm::dvec4>& texels, int resolution, glm::ivec2 first, glm::ivec2 last, int axis,
                int side) {
    const int before = side / 2, after = side - 1 - before;  // an even side reaches one texel further back
    const int length = last[axis] - first[axis] + 1, lines = last[1 - axis] - first[1 - axis] + 1;
    std::vector<glm::dvec4> line_texels(length);
    auto index = [&](int along, int line) {
        glm::ivec2 at;
        at[axis] = first[axis] + along;
        at[1 - axis] = first[1 - axis] + line;
        return std::size_t(at.y) * resolution + at.x;
    };
    for (int line = 0; line < lines; ++line) {
        for (int k = 0; k < length; ++k) line_texels[k] = texels[index(k, line)];
        for (int k = 0; k < length; ++k) {
            glm::dvec4 sum(0.0);
            for (int j = k - before; j <= k + after; ++j) sum += line_texels[std::clamp(j, 0, length - 1)];
            texels[index(k, line)] = sum / double(side);
        }
    }
}

}  // namespace

MomentMap blurred_moments(const DepthMap& depth, const ShadowSetup& setup, const ShadowFilter& filter) {
    const int n = depth.resolution;
    std::vector<glm::dvec4> texels(depth.codes.size());
    const MomentEncoding& encoding = filter_of(filter).moments;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) texels[depth.index(x, y)] = encoding.of_depth(depth.at(x, y), filter);
    for (const ShadowMap& map : setup.maps) {
        const glm::ivec2 first = texel_of(map, glm::dvec2(0.0), n), last = texel_of(map, glm::dvec2(1.0), n);
        blur_along(texels, n, first, last, 0, filter.kernel_size);
        blur_along(texels, n, first, last, 1, filter.kernel_size);
    }
    MomentMap out{n, std::vector<glm::vec4>(texels.size())};
    for (std::size_t i = 0; i < texels.size(); ++i)
        out.moments[i] = glm::vec4(encoding.stored ? encoding.stored(texels[i], filter) : texels[i]);
    return out;
}

glm::dvec4 sample_moments(const MomentMap& moments, const ShadowMap& map, const glm::dvec2& uv) {
    const int n = moments.resolution;
    const glm::ivec2 first = texel_of(map, glm::dvec2(0.0), n), last = texel_of(map, glm::dvec2(1.0), n);
    const glm::dvec2 t = texture_uv(map, uv) * double(n) - 0.5;  // texel centres at whole numbers
    const glm::dvec2 base = glm::floor(t), f = t - base;
    auto at = [&](int dx, int dy) {
        const glm::ivec2 texel = glm::clamp(glm::ivec2(base) + glm::ivec2(dx, dy), first, last);
        return glm::dvec4(moments.at(texel.x, texel.y));
    };
    return glm::mix(glm::mix(at(0, 0), at(1, 0), f.x), glm::mix(at(0, 1), at(1, 1), f.x), f.y);
}

}  // namespace shadowlab
