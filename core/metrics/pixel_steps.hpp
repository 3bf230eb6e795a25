#pragma once
// A receiver pixel of the camera image and its one-pixel steps: the points its right and down
// neighbours see on its surface, and the same view rays met with its halfway plane, the plane
// through the point whose normal lies halfway between the eye and the light. Lloyd's m and its
// perspective factor (metrics/shadow_error) and the storage bound (metrics/storage_bound) read them.
#include <cstddef>
#include <optional>
#include <glm/glm.hpp>

#include "reference/exact_shadows.hpp"
#include "scene/scene.hpp"

namespace shadowlab {

// Pixels judged: visible points of objects that receive shadows, on faces turned to the light
// (faces turned from it, or edge-on to it, are dark by shading whatever a map says).
bool receives(const Scene& scene, const ReferenceImage& reference, size_t pixel);

// The way the light travels at p.
glm::dvec3 along_light(const Light& light, const glm::dvec3& p);

struct PixelSteps {
    glm::dvec3 point;             // the pixel's visible point
    glm::dvec3 right, down;       // its neighbours' visible points on the same object
    glm::dvec3 right_on_halfway;  // the right neighbour's view ray met with the halfway plane
    glm::dvec3 down_on_halfway;   // the down neighbour's alike
    double right_sign = 1.0;      // -1 where the neighbour on the left stood in for the right one
    double down_sign = 1.0;       // -1 where the one above stood in for the one below
};

// The steps at pixel (x, y); nullopt where the pixel does not receive or no neighbour across or
// down lies on its object.
std::optional<PixelSteps> pixel_steps(const Scene& scene, const ReferenceImage& reference, int x, int y);

}  // namespace shadowlab
