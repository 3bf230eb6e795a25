#pragma once
// Contact shadows (screen-space shadows), as engines ship them beside their maps (UE's Contact
// Shadow Length, HDRP's Contact Shadows, Filament's and Godot's screen-space contact shadows): from
// the shaded point, a short march toward the light through the camera's own depth image. Where the
// image's surface lies in front of a sample by less than a thickness, something the camera sees
// stands between the point and the light: the point is in shadow whatever the map says. It restores
// the shadow a map loses where a caster meets its receiver (peter panning under a large normal
// offset or depth bias) and adds the small shadows finer than a texel; it knows nothing the camera
// does not see, and takes every surface to be `thickness` deep (thin geometry shadows too much).
#include <string>
#include <vector>
#include <glm/glm.hpp>

#include "scene/camera.hpp"
#include "scene/light.hpp"

namespace shadowlab {

// The most samples a march takes (contact_steps' range): each reads four pixels of the image.
constexpr int kMaxContactSteps = 64;

// The march: `steps` samples over `length` world units toward the light, each compared with the
// depth image. length 0 (the default) is off: nothing is marched, read or allocated.
struct ContactShadow {
    double length = 0.0;     // world units from the point toward the light
    int steps = 8;           // samples, at length k / steps for k = 1 .. steps
    double thickness = 0.1;  // world units: how far behind the image's surface a sample is still inside it

    bool on() const { return length > 0.0 && steps > 0; }
};

// "contact shadows over 0.5 (8 steps, surfaces 0.1 deep)", or "no contact shadows".
std::string describe(const ContactShadow& contact);

// The camera's depth image: per pixel (row 0 at the top) the window depth of the surface it sees
// (clip z / w mapped to [0, 1], as OpenGL's depth buffer holds it; 1 where it sees nothing), and the
// camera's matrices that project a sample onto it and take a window depth back to a view depth.
struct CameraDepthImage {
    int width = 0, height = 0;
    glm::dmat4 clip_from_world{1.0};       // the camera's projection × view (OpenGL clip space)
    glm::dmat4 world_from_clip{1.0};       // its inverse
    glm::dvec3 eye{0.0};                   // the camera's position
    glm::dvec3 view_axis{0.0, 0.0, -1.0};  // unit: a point's view depth is dot(p − eye, view_axis)
    std::vector<float> window_depth;

    CameraDepthImage() = default;
    CameraDepthImage(const Camera& camera, int width, int height);  // every pixel 1: nothing seen
    double view_depth_of(const glm::dvec3& p) const { return glm::dot(p - eye, view_axis); }
    double window_depth_of(const glm::dvec3& p) const;
};

// The contact shadow at the point p: 0 where a sample p + t · toward_light (t = length k / steps,
// toward_light unit) lies behind the image's surface by more than 0 and less than `thickness` (view
// depths), else 1. The surface under a sample is the window depth interpolated bilinearly between
// the four pixel centres around its projection, which is exact on a plane under either projection
// (window depth is affine across a plane's image): a sample just above its own receiver is never
// behind the receiver's pixels, however grazing the view. A sample behind the eye or off the image
// ends the march (nothing is known there). The GPU pass reads its depth image the same way
// (render/glsl/contact_shadow.glsl).
double contact_visibility(const ContactShadow& contact, const CameraDepthImage& image, const glm::dvec3& p,
                          const glm::dvec3& toward_light);

// A receiver's visibility under the maps times its contact shadow, marched toward `light` from p;
// the maps' own where they shadow it already (nothing to march). What every caller that judges
// the camera's pixels with contact shadows on applies (receiver_visibility, shimmer).
double with_contact_shadow(double map_visibility, const ContactShadow& contact, const CameraDepthImage& image,
                           const Light& light, const glm::dvec3& p);

}  // namespace shadowlab
