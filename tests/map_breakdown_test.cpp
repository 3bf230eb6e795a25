// A setup of several maps judged map by map, and its seams, on a hand-made image whose pixels'
// view depth grows with x: map 0 serves x < 5, map 1 the rest.
#include <gtest/gtest.h>

#include "metrics/map_breakdown.hpp"

using namespace shadowlab;

namespace {

constexpr int kWidth = 12, kHeight = 4;

ShadowSetup two_maps_split_at_depth_5() {
    ShadowSetup setup;
    setup.maps.resize(2);
    setup.selection.rule = MapSelection::Rule::view_depth;
    setup.selection.eye = glm::dvec3(0.0);
    setup.selection.view_axis = glm::dvec3(1.0, 0.0, 0.0);
    setup.selection.split_depths = {0.0, 5.0, 100.0};
    return setup;
}

// Every pixel a receiver that agrees, at view depth x + 0.5; m_perspective 1 for map 0's, 2 for map 1's.
struct Judged {
    ReferenceImage reference;
    ShadowError error;
};
Judged all_agreeing() {
    Judged j;
    j.reference.width = kWidth, j.reference.height = kHeight;
    j.error.verdicts.assign(kWidth * kHeight, PixelVerdict::agree);
    j.error.m_perspective_image.assign(kWidth * kHeight, 0.0f);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            j.reference.position.push_back({x + 0.5, 0.0, 0.0});
            j.error.m_perspective_image[y * kWidth + x] = x < 5 ? 1.0f : 2.0f;
        }
    return j;
}

}  // namespace

TEST(MapBreakdown, CountsEachMapsPixelsErrorsAndAliasing) {
    Judged j = all_agreeing();
    j.error.verdicts[0 * kWidth + 0] = PixelVerdict::false_shadow;  // map 0, far from the seam (x = 0)
    j.error.verdicts[1 * kWidth + 11] = PixelVerdict::false_light;  // map 1, far from it (x = 11)
    j.error.verdicts[2 * kWidth + 6] = PixelVerdict::false_light;   // map 1, 2 pixels from the boundary (x = 5)
    j.error.verdicts[3 * kWidth + 4] = PixelVerdict::none;          // not a receiver
    const MapBreakdown b = break_down_by_map(j.reference, j.error, two_maps_split_at_depth_5());
    ASSERT_EQ(b.maps.size(), 2u);
    EXPECT_EQ(b.maps[0].pixels, 5u * kHeight - 1);
    EXPECT_EQ(b.maps[1].pixels, 7u * kHeight);
    EXPECT_EQ(b.maps[0].misclassified, 1u);
    EXPECT_EQ(b.maps[1].misclassified, 2u);
    EXPECT_EQ(b.maps[0].m_perspective.max, 1.0);
    EXPECT_DOUBLE_EQ(b.maps[1].m_perspective.mean, 2.0);
    EXPECT_EQ(b.misclassified, 3u);
    // The boundary pixels are x = 4 and x = 5; within 3 pixels of them: x = 1 ... 8.
    EXPECT_EQ(b.near_seams, 1u);
    EXPECT_NEAR(b.seam_share(), 1.0 / 3.0, 1e-12);
    EXPECT_EQ(break_down_by_map(j.reference, j.error, two_maps_split_at_depth_5(), 0).near_seams, 0u);
}

TEST(MapBreakdown, OneMapHasNoSeams) {
    Judged j = all_agreeing();
    j.error.verdicts[5] = PixelVerdict::false_shadow;
    ShadowSetup one;
    one.maps.resize(1);
    const MapBreakdown b = break_down_by_map(j.reference, j.error, one);
    EXPECT_EQ(b.maps.at(0).pixels, size_t(kWidth * kHeight));
    EXPECT_EQ(b.near_seams, 0u);
    EXPECT_EQ(b.seam_share(), 0.0);
}
