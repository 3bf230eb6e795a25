// Two configurations compared pixel by pixel against one reference: a hand-made pair of verdict
// images whose counts are known, and two measured runs whose comparison must add up to each run's
// own misclassified pixels (only-A-right + both-wrong = B's wrong, both-right + only-A-right = A's
// right, the four classes partition the receiver pixels).
#include <gtest/gtest.h>

#include <cmath>

#include "math/invariant.hpp"
#include "metrics/measurement.hpp"
#include "metrics/verdict_comparison.hpp"
#include "registry/method.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using shadowlab::testing::source_path;

namespace {

ShadowError with_verdicts(std::vector<PixelVerdict> verdicts) {
    ShadowError e;
    for (PixelVerdict v : verdicts) e.receiver_pixels += v != PixelVerdict::none;
    e.verdicts = std::move(verdicts);
    return e;
}

size_t count(const VerdictComparison& c, PixelAgreement kind) {
    return static_cast<size_t>(std::count(c.pixels.begin(), c.pixels.end(), kind));
}

// A misclassified share of a run as a pixel count.
size_t pixels_of(double share, size_t receiver_pixels) {
    return static_cast<size_t>(std::llround(share * static_cast<double>(receiver_pixels)));
}

}  // namespace

TEST(VerdictComparison, EachPixelFallsInItsClassByHand) {
    using V = PixelVerdict;
    const ShadowError a =
        with_verdicts({V::none, V::agree, V::agree, V::false_shadow, V::false_light, V::false_shadow});
    const ShadowError b = with_verdicts({V::none, V::agree, V::false_light, V::agree, V::false_light, V::false_shadow});
    const VerdictComparison c = compare_verdicts(a, b);
    EXPECT_EQ(c.receiver_pixels, 5u);
    EXPECT_EQ(c.both_right, 1u);
    EXPECT_EQ(c.only_a_right, 1u);
    EXPECT_EQ(c.only_b_right, 1u);
    EXPECT_EQ(c.both_wrong, 2u);
    EXPECT_EQ(c.pixels, (std::vector<PixelAgreement>{PixelAgreement::none, PixelAgreement::both_right,
                                                     PixelAgreement::only_a_right, PixelAgreement::only_b_right,
                                                     PixelAgreement::both_wrong, PixelAgreement::both_wrong}));
    EXPECT_EQ(c.a_wrong(), 3u);
    EXPECT_EQ(c.b_wrong(), 3u);
    EXPECT_EQ(c.differing(), 2u);
}

TEST(VerdictComparison, ConfigurationsFromTwoReferencesAreRefused) {
    using V = PixelVerdict;
    EXPECT_THROW(compare_verdicts(with_verdicts({V::agree, V::none}), with_verdicts({V::agree, V::agree})),
                 InvariantBroken);
    EXPECT_THROW(compare_verdicts(with_verdicts({V::agree}), with_verdicts({V::agree, V::agree})), InvariantBroken);
}

// Two map methods on the default scene, one reference: the comparison's classes are each run's own
// misclassified pixels, split by what the other did there.
TEST(VerdictComparison, CountsAddUpToEachRunsMisclassifiedPixels) {
    const MeasureContext context = prepare_measurement(load_scene(source_path("data/scenes/default.json")), 320, 180);
    const Method& focused = method_or_throw("focused");
    const Method& lispsm = method_or_throw("lispsm");
    const Measurement a = measure(context, focused, resolve_settings("focused", focused.settings, {}), 256, -1.0);
    const Measurement b = measure(context, lispsm, resolve_settings("lispsm", lispsm.settings, {}), 256, -1.0);
    const VerdictComparison c = compare_verdicts(a.error, b.error);
    ASSERT_GT(c.receiver_pixels, 1000u);
    EXPECT_EQ(c.receiver_pixels, a.error.receiver_pixels);
    EXPECT_EQ(c.both_right + c.both_wrong + c.only_a_right + c.only_b_right, c.receiver_pixels);
    EXPECT_EQ(c.a_wrong(), pixels_of(a.error.misclassified, c.receiver_pixels));
    EXPECT_EQ(c.b_wrong(), pixels_of(b.error.misclassified, c.receiver_pixels));
    EXPECT_GT(c.a_wrong(), 0u);  // at 256² both misclassify some pixels, and not the same ones
    EXPECT_GT(c.differing(), 0u);
    EXPECT_EQ(count(c, PixelAgreement::both_right), c.both_right);
    EXPECT_EQ(count(c, PixelAgreement::only_a_right), c.only_a_right);
    EXPECT_EQ(count(c, PixelAgreement::only_b_right), c.only_b_right);
    EXPECT_EQ(count(c, PixelAgreement::both_wrong), c.both_wrong);

    // A run against itself: no pixel differs, and its wrong pixels are all wrong in both.
    const VerdictComparison same = compare_verdicts(a.error, a.error);
    EXPECT_EQ(same.differing(), 0u);
    EXPECT_EQ(same.both_wrong, c.a_wrong());
}
