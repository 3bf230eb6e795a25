// The Shadow map view of a VSM map's moments: the standard deviation √(m₂ − m₁²) of the blurred
// depth is bright only where the blur's texels hold different depths (the box's outline against the
// empty map) and black where they hold one. Read back from the picture, texel by texel (the view shows
// a 256² map at two screen pixels per texel), against the depth map the view was drawn from.
#include <gtest/gtest.h>

#include "lookup/shadow_filter.hpp"
#include "view_test_support.hpp"

namespace shadowlab {
namespace {

constexpr int kResolution = 256, kPixelsPerTexel = 2;
constexpr int kWidth = 768, kHeight = kResolution * kPixelsPerTexel;
constexpr int kImageLeft = (kWidth - kHeight) / 2;  // the square texture, centred
// The texel rows (from the top) the colour bar and the caption may cover.
constexpr int kFirstRow = 60, kLastRow = kResolution - 36;

// The spread of the depths the 3x3 blur around a texel reads (clamped to the texture).
float depth_span(const DepthMap& depth, int x, int y) {
    float lo = 1.0f, hi = 0.0f;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const float d = depth.at(std::clamp(x + dx, 0, kResolution - 1), std::clamp(y + dy, 0, kResolution - 1));
            lo = std::min(lo, d), hi = std::max(hi, d);
        }
    return hi - lo;
}

// For every filter whose moments hold a spread (vsm, evsm, msm).
TEST(MomentsView, TheDeviationIsBrightOnlyWhereTheBlurMixesDepths) {
    int filters = 0;
    for (const FilterDescriptor& filter : all_filters()) {
        if (filter.moments.deviation_words.empty()) continue;
        ++filters;
        const Inspection in = inspect_scene(testing::floating_box(kWidth, kHeight),
                                            {.method = "focused",
                                             .settings = {{"filter", filter.name}, {"kernel_size", "3"}},
                                             .resolution = kResolution});
        ViewOptions options;
        options.texture = TextureShown::moment_deviation;
        const RgbImage image = render_view(in, view_or_throw("shadowmap"), options, kWidth, kHeight);
        size_t flat = 0, flat_dark = 0, edges = 0, edges_bright = 0;
        for (int row = kFirstRow; row < kLastRow; ++row)
            for (int x = 0; x < kResolution; ++x) {
                const int y = kResolution - 1 - row;  // texel rows count up (v); the picture's from the top
                const unsigned char* c = image.at(kImageLeft + kPixelsPerTexel * x, kPixelsPerTexel * row);
                if (int(c[2]) > int(c[0]) + 60) continue;  // the camera frustum, drawn in blue over the texels
                const float span = depth_span(in.depth(), x, y);
                const int brightest = std::max({c[0], c[1], c[2]});
                if (span < 0.005f) ++flat, flat_dark += brightest < 25;
                if (span > 0.1f) ++edges, edges_bright += brightest > 100;
            }
        ASSERT_GT(edges, 40u) << filter.name << ": the box's outline should lie in the compared rows";
        EXPECT_GT(double(flat_dark) / flat, 0.99)
            << filter.name << ": " << flat_dark << " of " << flat << " texels of one depth";
        EXPECT_GT(double(edges_bright) / edges, 0.9)
            << filter.name << ": " << edges_bright << " of " << edges << " texels across an edge";
    }
    EXPECT_GE(filters, 3) << "vsm, evsm and msm at least";
}

// Under a filter that reads no moments, the option draws the depth, as the default does.
TEST(MomentsView, AFilterWithoutMomentsShowsTheDepth) {
    const Inspection in = testing::inspect(testing::floating_box(kWidth, kHeight), "focused", kResolution);
    ViewOptions moments;
    moments.texture = TextureShown::moment_deviation;
    const RgbImage asked = render_view(in, view_or_throw("shadowmap"), moments, kWidth, kHeight);
    const RgbImage depth = render_view(in, view_or_throw("shadowmap"), ViewOptions{}, kWidth, kHeight);
    size_t differ = 0;
    for (int row = kFirstRow; row < kLastRow; ++row)  // the caption says why; the texels are the same
        for (int x = 0; x < kWidth; ++x)
            differ += !std::equal(asked.at(x, row), asked.at(x, row) + 3, depth.at(x, row));
    EXPECT_EQ(differ, 0u);
}

}  // namespace
}  // namespace shadowlab
