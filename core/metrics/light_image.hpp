#pragma once
// The light's image plane: where a light ray lands, in the coordinates every shadow map of the light
// is a function of (a map's (u, v) is constant along a light ray, whatever its projection kind).
// A directional light has one chart, the plane across its direction (world units along the light
// space's x and y). A spot or point light has six, the faces of a cube about it: face k is the plane
// one unit along its axis (+x, -x, +y, -y, +z, -z), a direction's place on it the tangents of its
// angles off that axis. A spot's cone of any angle and an omni light's whole sphere of directions
// are covered, and a density (texels per unit area of a chart) integrates to the same count on
// whichever chart holds a direction: the change of variables between charts carries area and
// density inversely, so nothing that integrates over the charts depends on them.
#include <optional>
#include <glm/glm.hpp>

#include "scene/light.hpp"

namespace shadowlab {

struct LightImagePoint {
    int chart = 0;    // 0 for a directional light; the cube's face (0 .. 5) for a spot or point light
    glm::dvec2 at{};  // the place on the chart
};

class LightImage {
public:
    explicit LightImage(const Light& light);

    // The chart that holds p's light ray (a face: the one its direction leaves the cube through) and
    // p's place on it.
    LightImagePoint of(const glm::dvec3& p) const;
    // p's place on a given chart, for points near one it holds; nullopt where p's light ray does not
    // cross that face's plane (behind it as seen from the light).
    std::optional<glm::dvec2> on(int chart, const glm::dvec3& p) const;

private:
    Light light_;
    glm::dmat4 light_from_world_{1.0};  // directional: its basis (light_fit's light_basis)
};

}  // namespace shadowlab
