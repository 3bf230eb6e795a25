#include "lookup/contact_shadow.hpp"

#include <algorithm>
#include <cmath>

#include "methods/step_figures.hpp"

namespace shadowlab {
namespace {

// The image's window depth at continuous pixel coordinates (x right, y down; centres at whole
// numbers): bilinear between the four centres around it, each clamped into the image.
double window_depth_at(const CameraDepthImage& image, const glm::dvec2& at) {
    const glm::dvec2 corner = glm::floor(at), f = at - corner;
    const auto depth = [&](int dx, int dy) {
        const int x = std::clamp(int(corner.x) + dx, 0, image.width - 1);
        const int y = std::clamp(int(corner.y) + dy, 0, image.height - 1);
        return double(image.window_depth[size_t(y) * image.width + x]);
    };
    return glm::mix(glm::mix(depth(0, 0), depth(1, 0), f.x), glm::mix(depth(0, 1), depth(1, 1), f.x), f.y);
}

}  // namespace

std::string describe(const ContactShadow& contact) {
    if (!contact.on()) return "no contact shadows";
    return "contact shadows over " + label_number(contact.length) + " (" + std::to_string(contact.steps) +
           " steps, surfaces " + label_number(contact.thickness) + " deep)";
}

CameraDepthImage::CameraDepthImage(const Camera& camera, int width_, int height_)
    : width(width_),
      height(height_),
      clip_from_world(camera.projection_matrix() * camera.view_matrix()),
      world_from_clip(glm::inverse(clip_from_world)),
      eye(camera.position),
      view_axis(camera.view_direction()),
      window_depth(size_t(width_) * size_t(height_), 1.0f) {}

double CameraDepthImage::window_depth_of(const glm::dvec3& p) const {
    const glm::dvec4 clip = clip_from_world * glm::dvec4(p, 1.0);
    return 0.5 * clip.z / clip.w + 0.5;
}

double contact_visibility(const ContactShadow& contact, const CameraDepthImage& image, const glm::dvec3& p,
                          const glm::dvec3& toward_light) {
    for (int k = 1; k <= contact.steps; ++k) {
        const glm::dvec3 sample = p + toward_light * (contact.length * k / contact.steps);
        const glm::dvec4 clip = image.clip_from_world * glm::dvec4(sample, 1.0);
        if (clip.w <= 0.0) return 1.0;  // behind the eye
        const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
        if (std::abs(ndc.x) > 1.0 || std::abs(ndc.y) > 1.0) return 1.0;  // off the image
        const double window =
            window_depth_at(image, {(ndc.x + 1.0) * 0.5 * image.width - 0.5, (1.0 - ndc.y) * 0.5 * image.height - 0.5});
        if (window >= 1.0) continue;  // nothing seen there
        const glm::dvec4 seen = image.world_from_clip * glm::dvec4(ndc, 2.0 * window - 1.0, 1.0);
        const double behind = image.view_depth_of(sample) - image.view_depth_of(glm::dvec3(seen) / seen.w);
        if (behind > 0.0 && behind < contact.thickness) return 0.0;
    }
    return 1.0;
}

double with_contact_shadow(double map_visibility, const ContactShadow& contact, const CameraDepthImage& image,
                           const Light& light, const glm::dvec3& p) {
    if (map_visibility <= 0.0) return map_visibility;
    const glm::dvec3 toward_light = light.is_directional() ? -light.direction : glm::normalize(light.position - p);
    return map_visibility * contact_visibility(contact, image, p, toward_light);
}

}  // namespace shadowlab
