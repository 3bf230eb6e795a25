#pragma once
// Sample distribution shadow maps (Lauritzen, Salvi and Lefohn 2011): the depth range a shadow
// must cover is not the camera's near to far but the nearest and farthest receiver the camera
// actually sees, read back from its depth image. A street seen at eye height spans 0.5 to 400 by
// the frustum and perhaps 2 to 180 by what is visible; splits fit to that range spend no texel on
// the empty air before the first surface or beyond the last.
#include "methods/shadow_inputs.hpp"
#include "reference/exact_shadows.hpp"

namespace shadowlab {

// A depth image's receiver pixels reduced to their least and greatest view depth, widened by
// kVisibleDepthMargin each way (a view drawn at another size than the image may see a little
// nearer or farther) and kept within the camera's near and far. Empty when no receiver is seen.
DepthRange receiver_depth_range(const Scene& scene, const ReferenceImage& seen);

constexpr double kVisibleDepthMargin = 0.01;  // of each depth

// The same from a camera depth image traced for this purpose (primary rays only) at width x height.
DepthRange trace_receiver_depth_range(const Scene& scene, const WorldTriangles& triangles, int width, int height);

// The image's receiver pixels' points, and its height.
SeenReceivers receivers_seen(const Scene& scene, const ReferenceImage& seen);

// What a method that reads the camera's depth image takes from it: the depth range and the points
// (ShadowInputs::visible_depths, seen_receivers); from a traced image of width x height, or one at hand.
void read_depth_image(ShadowInputs& inputs, const Scene& scene, const ReferenceImage& seen);
void trace_depth_image(ShadowInputs& inputs, const Scene& scene, const WorldTriangles& triangles, int width,
                       int height);

}  // namespace shadowlab
