// The Error view's causes: a perspective map of the spot scene with a fifth of the slope-scaled
// bias (acne on the lit faces, receivers off the map, under-sampled edges). The picture is read
// back pixel for pixel (the view shows the judged image one screen pixel per image pixel): every
// misclassified pixel in its own cause's colour, that colour nowhere but within one pixel of the
// cause's pixels (its 3x3 blocks), and the legend's swatches one per cause present, ranked.
#include <gtest/gtest.h>

#include "metrics/diagnosis.hpp"
#include "view_test_support.hpp"

namespace shadowlab {
namespace {

constexpr int kWidth = 640, kHeight = 480;
// The rows the legend (top) and the caption (bottom) may cover; the legend's first row of swatches.
constexpr int kFirstRow = 40, kLastRow = kHeight - 30, kLegendFirstRow = 16;

Inspection weakly_biased_spot() {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/spot.json");
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    return inspect_scene(scene, {.method = "psm", .settings = {{"bias_slope", "0.2"}}, .resolution = 512});
}

RgbImage causes_view(const Inspection& in) {
    ViewOptions options;
    options.error = ErrorShown::causes;
    return render_view(in, view_or_throw("error"), options, kWidth, kHeight);
}

bool has_colour(const RgbImage& image, int x, int y, const std::array<unsigned char, 3>& colour) {
    const unsigned char* c = image.at(x, y);
    return c[0] == colour[0] && c[1] == colour[1] && c[2] == colour[2];
}

// Does a pixel of `cause` lie within one pixel of (x, y)?
bool near_cause(const ShadowError& e, int x, int y, PixelCause cause) {
    for (int ny = std::max(0, y - 1); ny <= std::min(kHeight - 1, y + 1); ++ny)
        for (int nx = std::max(0, x - 1); nx <= std::min(kWidth - 1, x + 1); ++nx)
            if (e.causes[static_cast<size_t>(ny) * kWidth + nx] == cause) return true;
    return false;
}

class CausesView : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        inspection_ = new Inspection(weakly_biased_spot());
        image_ = new RgbImage(causes_view(*inspection_));
    }
    static void TearDownTestSuite() {
        delete image_;
        delete inspection_;
    }
    static const ShadowError& error() { return inspection_->error(kWidth, kHeight); }
    static Inspection* inspection_;
    static RgbImage* image_;
};
Inspection* CausesView::inspection_ = nullptr;
RgbImage* CausesView::image_ = nullptr;

TEST_F(CausesView, PaintsEveryMisclassifiedPixelInItsCausesColourAndTheColourNowhereElse) {
    const Diagnosis d = count_causes(error());
    ASSERT_GE(d.causes.size(), 3u) << "the scene should show several causes";
    for (const CauseCount& cause : d.causes) {
        const CauseInfo& c = info(cause.kind);
        size_t own = 0, own_painted = 0, painted = 0, painted_near = 0;
        for (int y = kFirstRow; y < kLastRow; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const bool coloured = has_colour(*image_, x, y, c.colour);
                if (error().causes[static_cast<size_t>(y) * kWidth + x] == cause.kind) {
                    ++own;
                    own_painted += coloured;
                }
                if (coloured) {
                    ++painted;
                    painted_near += near_cause(error(), x, y, cause.kind);
                }
            }
        EXPECT_GT(own, 0u) << c.name;
        EXPECT_EQ(own_painted, own) << c.name;
        EXPECT_EQ(painted_near, painted) << c.name;
        EXPECT_LE(painted, 9 * own) << c.name;
    }
}

TEST_F(CausesView, TheLegendHasASwatchPerCauseRankedByPixels) {
    const Diagnosis d = count_causes(error());
    ASSERT_GE(d.causes.size(), 3u);
    std::vector<int> first_row_x;  // the swatch's left end, for the causes in the legend's first row
    for (const CauseCount& cause : d.causes) {
        int left = -1;
        bool found = false;
        for (int y = 0; y < kFirstRow && !found; ++y)
            for (int x = 0; x < kWidth && !found; ++x)
                if (has_colour(*image_, x, y, info(cause.kind).colour)) {
                    found = true;
                    if (y < kLegendFirstRow) left = x;
                }
        EXPECT_TRUE(found) << info(cause.kind).name << " has no swatch";
        if (left >= 0) first_row_x.push_back(left);
    }
    ASSERT_GE(first_row_x.size(), 2u);
    EXPECT_TRUE(std::is_sorted(first_row_x.begin(), first_row_x.end())) << "most pixels first, left to right";
}

}  // namespace
}  // namespace shadowlab
