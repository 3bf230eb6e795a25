#pragma once
// What every method starts from: camera, light, the scene's bounds, and the boxes of the objects
// that matter for this view (visible receivers, casters whose shadow can reach the view); and, when
// a method's settings ask for it, the view depths the camera actually sees on receivers.
#include <optional>
#include <vector>

#include "geometry/aabb.hpp"
#include "geometry/frustum.hpp"
#include "scene/scene.hpp"

namespace shadowlab {

// An object's world box and flags: computed once per scene, reused for every view.
struct ObjectBox {
    Aabb box;
    bool casts = true;
    bool receives = true;
};

std::vector<ObjectBox> object_boxes(const Scene& scene);

// View depths (along the camera's axis) from near to far; empty when far <= near.
struct DepthRange {
    double near = 0.0, far = 0.0;

    bool empty() const { return !(far > near); }
};

// The receiver points a camera depth image shows, one per receiver pixel, and the image's height in
// pixels (a pixel's footprint: methods/page_marking.hpp): what a virtual shadow map marks its pages from.
struct SeenReceivers {
    std::vector<glm::dvec3> points;
    int image_height = 0;
};

struct ShadowInputs {
    Camera camera;
    Light light;
    Frustum frustum;
    Aabb scene_bounds;            // all objects, padded so that it is never flat
    std::vector<Aabb> receivers;  // `receives` and the box meets the view frustum
    std::vector<Aabb> casters;    // `casts` and the box's shadow can reach the view frustum
    // The nearest and farthest receiver the camera's depth image shows (sample distribution shadow
    // maps): measured only for a method whose settings read it (Method::wants_visible_depths), by
    // the caller, who has the scene's triangles (reference/visible_depths.hpp); an empty range when
    // no receiver is visible. None when not measured.
    std::optional<DepthRange> visible_depths;
    std::optional<SeenReceivers> seen_receivers;  // the same image's points, measured with visible_depths
    // Texels per side of the texture the setup will be drawn into: a virtual map's physical pool.
    int texture_resolution = 1024;

    std::vector<glm::dvec3> receiver_points() const;  // 8 corners per box
    std::vector<glm::dvec3> caster_points() const;
};

ShadowInputs gather_inputs(const Camera& camera, const Light& light, const std::vector<ObjectBox>& objects);
ShadowInputs gather_inputs(const Scene& scene);

}  // namespace shadowlab
