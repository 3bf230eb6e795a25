// The float clipper: clipping a box keeps a closed convex polyhedron with the right volume.
#include <gtest/gtest.h>

#include <random>

#include "geometry/convex_polyhedron.hpp"

using namespace shadowlab;

namespace {

const Aabb unit_box{glm::dvec3(0.0), glm::dvec3(1.0)};

}  // namespace

TEST(ConvexPolyhedron, BoxIsClosedConvexWithItsVolume) {
    const ConvexPolyhedron box = ConvexPolyhedron::box({{-1, -2, -3}, {1, 2, 3}});
    EXPECT_TRUE(is_closed(box));
    EXPECT_TRUE(is_convex(box, 1e-12));
    EXPECT_NEAR(box.volume(), 2 * 4 * 6, 1e-12);
}

TEST(ConvexPolyhedron, ClipThroughCentreHalvesTheBox) {
    const ConvexPolyhedron half =
        clip(ConvexPolyhedron::box(unit_box), Plane::through({0.5, 0.5, 0.5}, {1, 0, 0}), 1e-12);
    EXPECT_TRUE(is_closed(half));
    EXPECT_TRUE(is_convex(half, 1e-12));
    EXPECT_NEAR(half.volume(), 0.5, 1e-12);
    EXPECT_LE(half.bounds().max.x, 0.5 + 1e-12);
}

TEST(ConvexPolyhedron, CornerCutRemovesATetrahedron) {
    // The plane x + y + z = 0.5 cuts off the corner at the origin: a tetrahedron of volume 0.5^3 / 6.
    const ConvexPolyhedron cut =
        clip(ConvexPolyhedron::box(unit_box), Plane::through({0.5, 0, 0}, {-1, -1, -1}), 1e-12);
    EXPECT_TRUE(is_closed(cut));
    EXPECT_NEAR(cut.volume(), 1.0 - 0.125 / 6.0, 1e-12);
    EXPECT_EQ(cut.faces.size(), 7u);
}

TEST(ConvexPolyhedron, ClipThroughAVertexAndAnEdgeStaysClosed) {
    // The plane x + y = 1 passes through the edge x=1,y=0 and x=0,y=1: a prism of half the volume.
    const ConvexPolyhedron prism = clip(ConvexPolyhedron::box(unit_box), Plane::through({1, 0, 0}, {1, 1, 0}), 1e-12);
    EXPECT_TRUE(is_closed(prism));
    EXPECT_TRUE(is_convex(prism, 1e-12));
    EXPECT_NEAR(prism.volume(), 0.5, 1e-12);
    EXPECT_EQ(prism.vertices.size(), 6u);
}

TEST(ConvexPolyhedron, PlaneMissingOrContainingTheBox) {
    const ConvexPolyhedron box = ConvexPolyhedron::box(unit_box);
    EXPECT_TRUE(clip(box, Plane::through({2, 0, 0}, {-1, 0, 0}), 1e-12).empty());              // all outside
    EXPECT_NEAR(clip(box, Plane::through({2, 0, 0}, {1, 0, 0}), 1e-12).volume(), 1.0, 1e-15);  // all inside
    EXPECT_TRUE(clip(box, Plane::through({1, 0, 0}, {-1, 0, 0}), 1e-12).empty());              // touching a face
}

TEST(ConvexPolyhedron, RandomCutsKeepClosedConvexAndShrinkingVolume) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        ConvexPolyhedron poly = ConvexPolyhedron::box({glm::dvec3(-1.0), glm::dvec3(1.0)});
        double volume = poly.volume();
        for (int k = 0; k < 12 && !poly.empty(); ++k) {
            const glm::dvec3 n{u(rng), u(rng), u(rng)};
            if (glm::length(n) < 1e-3) continue;
            poly = clip(poly, Plane::through(0.7 * glm::dvec3(u(rng), u(rng), u(rng)), n), 1e-12);
            if (poly.empty()) break;
            ASSERT_TRUE(is_closed(poly)) << "trial " << trial << " cut " << k;
            ASSERT_TRUE(is_convex(poly, 1e-9)) << "trial " << trial << " cut " << k;
            EXPECT_LE(poly.volume(), volume + 1e-12);
            volume = poly.volume();
        }
    }
}
