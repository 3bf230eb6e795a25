// The Flatland view (under Xvfb): the plane of the view and the light drawn in its own frame, the
// eye at the left. LiSPSM's texel boundaries crowd near the eye and spread out far from it, so the
// picture's left half holds most of their pixels; a uniform map's fall evenly; the frustum, B and the
// warp frustum are drawn in their roles' colours; a technique has no texels to draw.
#include <gtest/gtest.h>

#include "render/map_overlay.hpp"
#include "view_test_support.hpp"
#include "views/space_parts.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 1000, kHeight = 600, kResolution = 1024;
constexpr int kLegendAndCaption = 40;  // rows at the top and the bottom the texts may cover

RgbImage flatland_picture(const std::string& method) {
    const Inspection in = inspect(shipped_scene("teaching", kWidth, kHeight), method, kResolution);
    return render_view(in, view_or_throw("flatland"), {}, kWidth, kHeight);
}

bool has_colour(const unsigned char* c, const glm::dvec3& colour) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(c[i] - 255.0 * colour[i]) > 12.0) return false;
    return true;
}

// Pixels of `colour` in the picture's left and right halves, the legend's and caption's rows left out.
struct Halves {
    size_t left = 0, right = 0;
    size_t both() const { return left + right; }
};
Halves pixels_of(const RgbImage& image, const glm::dvec3& colour) {
    Halves h;
    for (int y = kLegendAndCaption; y < image.height - kLegendAndCaption; ++y)
        for (int x = 0; x < image.width; ++x)
            if (has_colour(image.at(x, y), colour)) (x < image.width / 2 ? h.left : h.right) += 1;
    return h;
}

const glm::dvec3 kFirstMapColour(kMapPalette[0]);

TEST(FlatlandView, LispsmTexelLinesCrowdNearTheEye) {
    const RgbImage picture = flatland_picture("lispsm");
    const Halves lines = pixels_of(picture, kFirstMapColour);
    ASSERT_GT(lines.right, 500u);  // the far lines are drawn
    EXPECT_GT(lines.left, 2 * lines.right) << lines.left << " left, " << lines.right << " right";
    for (Role role : {Role::view, Role::focus, Role::map})
        EXPECT_GT(pixels_of(picture, role_style(role).colour).both(), 300u) << role_style(role).legend;
}

TEST(FlatlandView, UniformTexelLinesFallEvenly) {
    const Halves lines = pixels_of(flatland_picture("uniform"), kFirstMapColour);
    ASSERT_GT(lines.right, 500u);
    EXPECT_NEAR(static_cast<double>(lines.left) / lines.right, 1.0, 0.35) << lines.left << " left, " << lines.right;
}

TEST(FlatlandView, ATechniqueHasNoTexelsToDraw) {
    const RgbImage picture = flatland_picture("volumes");
    EXPECT_EQ(pixels_of(picture, kFirstMapColour).both(), 0u);
    EXPECT_EQ(pixels_of(picture, role_style(Role::focus).colour).both(), 0u);
}

}  // namespace
