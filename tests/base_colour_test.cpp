// Materials' colours in core (scene/base_colour.hpp): IEC 61966-2-1's transfer functions, a colour
// texture read as its file stores it (bottom row first, as the alpha texture of the same image), and
// the importer's material colours carried back from its child process unchanged.
#include <gtest/gtest.h>

#include "scene/base_colour.hpp"
#include "scene/file_bytes.hpp"
#include "scene/mesh_transfer.hpp"
#include "scene/png_alpha.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using shadowlab::testing::source_path;

TEST(BaseColour, SrgbTransferFunctionsInvertEachOtherAndMeetAtTheKnee) {
    int checked = 0;
    for (int level = 0; level <= 255; ++level, ++checked) {
        const double encoded = level / 255.0;
        EXPECT_NEAR(srgb_from_linear(linear_from_srgb(encoded)), encoded, 1e-12) << level;
    }
    EXPECT_EQ(checked, 256);
    // The two pieces agree where they join (IEC 61966-2-1: 0.04045 encoded, 0.0031308 linear).
    EXPECT_NEAR(linear_from_srgb(0.04045), 0.04045 / 12.92, 1e-6);
    EXPECT_NEAR(linear_from_srgb(0.04045 + 1e-9), 0.04045 / 12.92, 1e-6);
    EXPECT_NEAR(srgb_from_linear(0.5), 0.735357, 1e-6);
    const glm::dvec3 clamped = shown_factor(BaseColour{.factor = {2.0, -1.0, 1.0}, .texture = nullptr});
    EXPECT_NEAR(clamped.r, 1.0, 1e-12);  // beyond [0, 1]: clamped before encoding
    EXPECT_NEAR(clamped.g, 0.0, 1e-12);
    EXPECT_NEAR(clamped.b, 1.0, 1e-12);
}

TEST(BaseColour, ColourTextureKeepsTheFilesBytesBottomRowFirstAsTheAlphaTextureDoes) {
    const std::string file = source_path("data/scenes/fence_holes.png");
    const ColourTexture colour = decode_colour_texture(file_bytes(file), file);
    const AlphaTexture alpha = decode_png_alpha(file_bytes(file), file);
    ASSERT_EQ(colour.width, alpha.width);
    ASSERT_EQ(colour.height, alpha.height);
    ASSERT_EQ(colour.srgb_rgba.size(), 4u * colour.width * colour.height);
    std::size_t holes = 0;
    for (int y = 0; y < colour.height; ++y)
        for (int x = 0; x < colour.width; ++x) {
            const std::size_t texel = std::size_t(y) * colour.width + x;
            const std::uint8_t* rgba = &colour.srgb_rgba[4 * texel];
            EXPECT_EQ(rgba[0], 110);  // make_fence.py's brown everywhere, its alpha the holes
            EXPECT_EQ(rgba[1], 84);
            EXPECT_EQ(rgba[2], 60);
            EXPECT_FLOAT_EQ(rgba[3] / 255.0f, alpha.alpha[texel]);
            holes += rgba[3] == 0;
        }
    EXPECT_EQ(holes, 8u * 4u * 5u * 5u);  // 8 x 4 cells, each a 5 x 5 hole
    // Row 0 is the image's bottom: the rail (the file's top 8 rows) is the last rows here.
    EXPECT_EQ(colour.srgb_rgba[4 * (std::size_t(colour.height - 1) * colour.width) + 3], 255);
    EXPECT_THROW(decode_colour_texture("GIF89a", "x.gif"), std::invalid_argument);
}

TEST(BaseColour, MaterialColoursCrossFromTheImportersChildUnchanged) {
    NodeMesh node{.node_name = "quad", .mesh = {}};
    node.mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    node.mesh.triangles = {{0, 1, 2}};
    node.mesh.colour_sources = {{}, {.named = true, .diffuse = {1.0, 0.5, 0.2}, .texture = "sub/checker.png"}};
    const std::string bytes = encode_node_meshes({node});
    const std::optional<std::vector<NodeMesh>> back = decode_node_meshes(bytes);
    ASSERT_TRUE(back && back->size() == 1);
    const std::vector<MaterialColourSource>& sources = back->front().mesh.colour_sources;
    ASSERT_EQ(sources.size(), 2u);
    EXPECT_FALSE(sources[0].named);
    EXPECT_TRUE(sources[1].named);
    EXPECT_EQ(sources[1].diffuse, glm::dvec3(1.0, 0.5, 0.2));
    EXPECT_EQ(sources[1].texture, "sub/checker.png");
    EXPECT_FALSE(decode_node_meshes(bytes.substr(0, bytes.size() - 9)));  // cut inside the colours: refused
}
