// The Error view's signed visibility error: a PCF-filtered map of a box floating over the ground
// under a sun 6° in radius (a penumbra much wider than the filter's), judged against the soft
// reference. The picture is read back pixel for pixel (the view shows the judged image one screen
// pixel per image pixel): red or blue exactly where |method − reference| is large, in the sign's
// colour, white where it is about 0, the usual greys where nothing is judged. And the automatic
// choice: signed where shadows are soft, verdicts where they are hard.
#include <gtest/gtest.h>

#include "view_test_support.hpp"
#include "views/error_colours.hpp"

namespace shadowlab {
namespace {

constexpr int kWidth = 640, kHeight = 480;
// The rows the colour bar (top) and the caption (bottom) may cover.
constexpr int kFirstRow = 130, kLastRow = kHeight - 80;

Inspection soft_pcf_inspection(double angular_radius_deg, const std::string& filter) {
    Scene scene = testing::floating_box(kWidth, kHeight);
    scene.light.angular_radius_deg = angular_radius_deg;
    return inspect_scene(scene, {.method = "focused", .settings = {{"filter", filter}}, .resolution = 512});
}

struct Shares {
    size_t large = 0, large_with_its_sign = 0;    // |error| > 0.3
    size_t exact = 0, exact_white = 0;            // |error| < 0.02
    size_t coloured = 0, coloured_and_large = 0;  // red and blue channels apart by more than 30
    size_t unjudged = 0, unjudged_grey = 0;
};

Shares compare(const RgbImage& image, const VisibilityError& v) {
    Shares s;
    for (int y = kFirstRow; y < kLastRow; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const size_t i = static_cast<size_t>(y) * kWidth + x;
            const unsigned char* c = image.at(x, y);
            const int red_over_blue = int(c[0]) - int(c[2]);
            const double error = v.signed_error[i];
            if (v.image[i] < 0.0f) {
                ++s.unjudged;
                s.unjudged_grey += std::abs(int(c[0]) - int(c[1])) < 8 && c[0] <= 130;
                continue;
            }
            if (std::abs(error) > 0.3) {
                ++s.large;
                s.large_with_its_sign += error > 0.0 ? red_over_blue > 30 : red_over_blue < -30;
            }
            if (std::abs(error) < 0.02) {
                ++s.exact;
                s.exact_white += std::min({c[0], c[1], c[2]}) >= 238;
            }
            if (std::abs(red_over_blue) > 30) {
                ++s.coloured;
                s.coloured_and_large += std::abs(error) > 0.2;
            }
        }
    return s;
}

TEST(SignedErrorView, PaintsTheErrorWhereItIsLargeAndWhiteWhereItIsZero) {
    const Inspection in = soft_pcf_inspection(6.0, "pcf");
    ViewOptions options;
    options.error = ErrorShown::signed_visibility;
    const RgbImage image = render_view(in, view_or_throw("error"), options, kWidth, kHeight);
    const VisibilityError& v = in.error(kWidth, kHeight).visibility;
    const Shares s = compare(image, v);
    ASSERT_GT(s.large, 100u) << "the scene should show a penumbra the filter gets wrong";
    ASSERT_GT(s.exact, 10000u);
    EXPECT_GT(double(s.large_with_its_sign) / s.large, 0.95) << s.large_with_its_sign << " of " << s.large;
    EXPECT_GT(double(s.exact_white) / s.exact, 0.99) << s.exact_white << " of " << s.exact;
    EXPECT_GT(double(s.coloured_and_large) / s.coloured, 0.95) << s.coloured_and_large << " of " << s.coloured;
    EXPECT_GT(double(s.unjudged_grey) / s.unjudged, 0.99) << s.unjudged_grey << " of " << s.unjudged;
}

TEST(SignedErrorView, IsTheAutomaticChoiceWhereShadowsAreSoft) {
    EXPECT_TRUE(shows_signed_error(soft_pcf_inspection(3.0, "hard"), ErrorShown::automatic));  // a sun with a size
    EXPECT_TRUE(shows_signed_error(soft_pcf_inspection(0.0, "pcf"), ErrorShown::automatic));   // a filter that blends
    const Inspection hard = soft_pcf_inspection(0.0, "hard");
    EXPECT_FALSE(shows_signed_error(hard, ErrorShown::automatic));
    EXPECT_TRUE(shows_signed_error(hard, ErrorShown::signed_visibility));
    EXPECT_FALSE(shows_signed_error(soft_pcf_inspection(3.0, "pcf"), ErrorShown::verdicts));
}

}  // namespace
}  // namespace shadowlab
