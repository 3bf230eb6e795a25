// Every registered projection kind (maps/projection_kind.hpp) against itself: its inverse undoes its
// mapping inside the unit cube, the one CPU lookup reads a map exactly through its descriptor, and its
// derivatives are those of its mapping.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <glm/gtc/matrix_transform.hpp>

#include "maps/clip_conventions.hpp"
#include "maps/map_lookup.hpp"
#include "maps/projection_kind.hpp"

using namespace shadowlab;

namespace {

const glm::dvec3 kLight{0.0, 5.0, 0.0};

// A map of the kind seen from kLight: every kind reads the fields it uses. Looking down -y, a 90°
// perspective world_to_uvz (near 1, far 11) or the paraboloid's frame (+z is world -y), near and far;
// a log perspective looks across the light as LogPSM's warp does (along -z, its depth the light's -y
// and its w the distance along -z, logarithmic over the same 1 to 11).
ShadowMap map_of(Projection projection) {
    const glm::dmat4 perspective = glm::perspective(glm::radians(90.0), 1.0, 1.0, 11.0);
    const glm::dmat4 down = uvz_from_clip({}) * perspective * glm::lookAt(kLight, glm::dvec3(0.0), glm::dvec3(0, 0, 1));
    glm::dmat4 across =
        uvz_from_clip({}) * perspective * glm::lookAt(kLight, kLight - glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0));
    for (int column = 0; column < 4; ++column)
        std::swap(across[column][1], across[column][2]);  // depth along the light
    return {
        .projection = projection,
        .world_to_uvz = projection == Projection::log_perspective ? across : down,
        .paraboloid = {.centre = kLight,
                       .frame_from_world = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0)),
                       .near = 1.0,
                       .far = 11.0},
        .log_warp = {.near = 1.0, .far = 11.0}};
}

// The light's direction at p for map_of's map: a directional light along the log perspective's depth
// (its centre is no light: depth is constant along the rays from it), from kLight for the others.
glm::dvec3 light_direction_at(Projection projection, const glm::dvec3& p) {
    return projection == Projection::log_perspective ? glm::dvec3(0, -1, 0) : glm::normalize(p - kLight);
}

// Points of the unit cube's inside, u, v, d in {0.1, 0.3, ..., 0.9}.
std::vector<glm::dvec3> unit_cube_points() {
    std::vector<glm::dvec3> points;
    for (double u = 0.1; u < 1.0; u += 0.2)
        for (double v = 0.1; v < 1.0; v += 0.2)
            for (double d = 0.1; d < 1.0; d += 0.2) points.push_back({u, v, d});
    return points;
}

glm::dvec3 divided(const glm::dvec4& h) { return glm::dvec3(h) / h.w; }

}  // namespace

TEST(ProjectionKinds, RegisteredOnceByNameAndAnUnregisteredKindIsANamedError) {
    const std::vector<Projection> kinds = projection_kinds();
    ASSERT_FALSE(kinds.empty());
    std::set<std::string> names;
    for (Projection kind : kinds) {
        EXPECT_TRUE(names.insert(projection_kind(kind).name).second) << projection_kind(kind).name;
        EXPECT_EQ(std::string(to_string(kind)), projection_kind(kind).name);
    }
    EXPECT_THROW(projection_kind(Projection(int(kinds.size()))), std::invalid_argument);
}

TEST(ProjectionKinds, TheInverseUndoesTheMappingInsideTheUnitCube) {
    for (Projection projection : projection_kinds()) {
        const ShadowMap map = map_of(projection);
        const ProjectionKind& kind = projection_kind(map);
        for (const glm::dvec3& uvz : unit_cube_points()) {
            const glm::dvec3 world = kind.world_of(map, uvz);
            const glm::dvec4 h = kind.homogeneous(map, world);
            ASSERT_GT(h.w, 0.0) << kind.name;
            EXPECT_NEAR(glm::distance(divided(h), uvz), 0.0, 1e-9) << kind.name;
            EXPECT_NEAR(glm::distance(kind.world_of(map, divided(h)), world), 0.0, 1e-8) << kind.name;
        }
    }
}

// The CPU lookup of a setup of one map: exactly its kind's mapping and clip distance.
TEST(ProjectionKinds, TheLookupReadsTheMapThroughItsDescriptor) {
    for (Projection projection : projection_kinds()) {
        const ShadowSetup setup{.maps = {map_of(projection)}};
        const ShadowMap& map = setup.maps[0];
        const ProjectionKind& kind = projection_kind(map);
        for (const glm::dvec3& uvz : unit_cube_points()) {
            const glm::dvec3 world = kind.world_of(map, uvz);
            const glm::dvec4 h = kind.homogeneous(map, world);
            EXPECT_EQ(map_homogeneous(map, world), h) << kind.name;
            EXPECT_EQ(hemisphere_side(map, world), kind.clip_distance ? kind.clip_distance(map, world) : 1.0);
            const std::optional<MapLookup> at = look_up(setup, world, 0.0);
            ASSERT_TRUE(at) << kind.name << " at " << uvz.x << ", " << uvz.y << ", " << uvz.z;
            EXPECT_EQ(at->uv, glm::dvec2(h) / h.w) << kind.name;
            EXPECT_EQ(at->depth, h.z / h.w) << kind.name;
        }
    }
}

// Along the ray from the light through each point (light_direction_at): the derivatives match central
// differences of the mapping, and distance_back_to_depth finds the point 0.3 back toward the light by
// its depth.
TEST(ProjectionKinds, TheDerivativesAreThoseOfTheMapping) {
    constexpr double step = 1e-5, back = 0.3;
    for (Projection projection : projection_kinds()) {
        const ShadowMap map = map_of(projection);
        const ProjectionKind& kind = projection_kind(map);
        for (const glm::dvec3& uvz : unit_cube_points()) {
            const glm::dvec3 p = kind.world_of(map, uvz), l = light_direction_at(projection, p);
            const glm::dvec3 central =
                (divided(kind.homogeneous(map, p + step * l)) - divided(kind.homogeneous(map, p - step * l))) /
                (2.0 * step);
            EXPECT_NEAR(glm::distance(kind.uv_derivative(map, p, l), glm::dvec2(central)), 0.0, 1e-6) << kind.name;
            EXPECT_NEAR(kind.depth_slope(map, l, p), central.z, 1e-6) << kind.name;
            const double depth_back = divided(kind.homogeneous(map, p - back * l)).z;
            EXPECT_NEAR(kind.distance_back_to_depth(map, l, p, depth_back), back, 1e-9) << kind.name;
        }
    }
}

// A reversed-Z format draws each map's reversed depth: the same (u, v), its depth s = 1 − d.
TEST(ProjectionKinds, TheReversedDepthIsOneMinusTheDepthFromTheKindsOwnTerms) {
    for (Projection projection : projection_kinds()) {
        const ShadowMap map = map_of(projection), reversed = with_reversed_depth(map);
        const ProjectionKind& kind = projection_kind(map);
        EXPECT_EQ(reversed.projection, map.projection) << kind.name;
        EXPECT_EQ(reversed.viewport, map.viewport) << kind.name;
        for (const glm::dvec3& uvz : unit_cube_points()) {
            const glm::dvec3 world = kind.world_of(map, uvz);
            const glm::dvec3 plain = world_to_uvz(map, world), flipped = world_to_uvz(reversed, world);
            EXPECT_NEAR(glm::distance(glm::dvec2(flipped), glm::dvec2(plain)), 0.0, 1e-12) << kind.name;
            EXPECT_NEAR(flipped.z, 1.0 - plain.z, 1e-12) << kind.name;
        }
    }
}

// From the kind's own terms, not 1 − d after the fact: a paraboloid's s = (|q| − far) / (near − far)
// is exact to the last bit a hair before its far end (|q| − far is exact there), where 1 − d would
// keep only the bits of d's rounding, 1e-16 of an s of 1e-10.
TEST(ProjectionKinds, AParaboloidsReversedDepthKeepsItsPrecisionNearTheFarEnd) {
    const ShadowMap map = map_of(Projection::paraboloid);
    const double before_far = std::ldexp(1.0, -30);  // the range is 10 units: s = before_far / 10
    const glm::dvec3 p = kLight + glm::dvec3(0.0, -(map.paraboloid.far - before_far), 0.0);  // on the frame's +z
    const double s = world_to_uvz(with_reversed_depth(map), p).z;
    EXPECT_NEAR(s, before_far / 10.0, 1e-25);
    EXPECT_GT(std::abs((1.0 - world_to_uvz(map, p).z) - before_far / 10.0), 1e-25) << "1 − d loses it";
}
