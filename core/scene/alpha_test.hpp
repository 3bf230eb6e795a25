#pragma once
// Alpha-tested casters (glTF 2.0 "alphaMode": MASK with its "alphaCutoff"): a material's alpha is its
// base colour texture's alpha at the point's texture coordinates times the factor's alpha, and the
// surface is there where that alpha is at least the cutoff, absent elsewhere (foliage, fences, grates).
#include <array>
#include <memory>
#include <string>
#include <vector>
#include <glm/glm.hpp>

namespace shadowlab {

// An image's alpha channel in [0, 1], row 0 its bottom row: texture coordinates as Assimp gives them
// (v up, OpenGL's convention; Assimp turns glTF's v down into it), so (u, v) = (0, 0) is the
// bottom-left corner of the image.
struct AlphaTexture {
    int width = 0, height = 0;
    std::vector<float> alpha;  // row-major, y * width + x, y from the bottom
    std::string file;          // where it was read from, for messages

    // The nearest texel's alpha, the texture repeated beyond [0, 1) (glTF's default sampler wraps;
    // nearest, so that the CPU raster, the GPU and the reference read the same texel).
    float at(const glm::dvec2& uv) const;
};

struct AlphaTest {
    std::shared_ptr<const AlphaTexture> texture;  // null: the factor alone
    double factor = 1.0;                          // the base colour factor's alpha
    double cutoff = 0.5;                          // alphaCutoff (glTF's default 0.5)

    double alpha(const glm::dvec2& uv) const { return texture ? factor * texture->at(uv) : factor; }
    // Is the surface there at these texture coordinates? glTF: opaque where alpha >= cutoff.
    bool keeps(const glm::dvec2& uv) const { return alpha(uv) >= cutoff; }
};

// One triangle's alpha test: its material's and its corners' texture coordinates.
struct TriangleAlpha {
    std::shared_ptr<const AlphaTest> test;  // null: opaque
    std::array<glm::dvec2, 3> uv{};

    // The texture coordinates at barycentric weights b1, b2 of the second and third corners.
    glm::dvec2 uv_at(double b1, double b2) const { return (1.0 - b1 - b2) * uv[0] + b1 * uv[1] + b2 * uv[2]; }
    bool keeps(double b1, double b2) const { return !test || test->keeps(uv_at(b1, b2)); }
};

}  // namespace shadowlab
