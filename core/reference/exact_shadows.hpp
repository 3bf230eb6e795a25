#pragma once
// The ground truth shadow maps are measured against: for each camera pixel, the visible point and
// whether it sees the light, by ray tracing the scene's triangles.
#include <cstdint>
#include <vector>
#include <glm/glm.hpp>

#include "scene/scene.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

// Per pixel, row-major with row 0 at the top of the image.
struct ReferenceImage {
    int width = 0, height = 0;
    std::vector<glm::dvec3> position;  // the visible point; (0, 0, 0) where nothing is visible
    std::vector<int> object;           // its object's index in Scene::objects; -1 where nothing is visible
    std::vector<uint8_t> visible;      // the primary ray meets a triangle between near and far
    std::vector<uint8_t> lit;          // visible, and no caster triangle lies between it and the light
    std::vector<float> facing;  // cos of the angle between the seen side's normal and the light: <= 0 in its own shade
    std::vector<glm::dvec3> normal;  // the seen side's unit normal; (0, 0, 0) where nothing is visible or not traced
    // soft_reference only: the share of an area light each visible point sees, from light_samples rays.
    std::vector<float> visibility;
    int light_samples = 0;
};

// One primary ray through each pixel centre of the camera's projection (width x height pixels
// spanning its full field of view), then a shadow ray from the visible point toward the light:
// along -direction to infinity for a directional light, up to the position for spot and point
// lights (the spot's cone is not applied). Rays are traced in camera-relative coordinates, so the
// verdicts do not change when the scene is moved far from the origin. The shadow ray starts a
// small offset off the surface (64 float32 steps of the local coordinates), along the triangle's
// normal turned toward the light, so that its own triangle never blocks it; a closed object still shadows its faces
// turned from the light (the ray crosses the object), while a lone plane seen from its side away
// from the light counts as lit: the test is occlusion, as a shadow map sees it, not shading.
ReferenceImage exact_reference(const Scene& scene, const WorldTriangles& triangles, int width, int height);

// The soft shadows of an area light (Light::is_area): exact_reference's image, and per visible
// pixel the share of the light its point sees, from `samples` stratified shadow rays over the sun's
// disc of directions or the sphere light's disc facing the point (reference/light_samples.hpp;
// their standard error: visibility_standard_error). A point light's share is 0 or 1.
constexpr int kDefaultLightSamples = 64;  // shadow rays per pixel unless a caller asks for more
// The reference a scene's light calls for: soft_reference with `light_samples` rays per pixel when
// the light has a size (Light::is_area), else exact_reference.
ReferenceImage light_reference(const Scene& scene, const WorldTriangles& triangles, int width, int height,
                               int light_samples = kDefaultLightSamples);
ReferenceImage soft_reference(const Scene& scene, const WorldTriangles& triangles, int width, int height, int samples);

// The primary rays alone: the camera's depth image (position, object, visible), its lit and facing
// left at 0. What sample-distribution bounds read (visible_depths.hpp), for a fraction of the cost.
ReferenceImage visible_points(const Scene& scene, const WorldTriangles& triangles, int width, int height);

}  // namespace shadowlab
