#pragma once
// XPSM's trace (methods/xpsm.cpp): each group of Gusev's steps recorded with its values and the
// paper's figures (Fig. 5: light space seen from the light), one call a group, so that xpsm.cpp
// reads as the steps. Nothing is recorded when the trace is null.
#include <cmath>
#include <vector>
#include <glm/glm.hpp>

#include "geometry/aabb.hpp"
#include "maps/shadow_map.hpp"
#include "methods/warp_common.hpp"
#include "trace/trace.hpp"

namespace shadowlab::xpsm {

// Light-space points of the casters and the receivers (steps 1 and 4).
struct LightSpacePoints {
    std::vector<glm::dvec3> casters, receivers;
};

// An interval of positions along unitP.
struct Interval {
    double min = INFINITY, max = -INFINITY;
};

// Steps 4 to 7: the projection vector, and what its length was chosen from.
struct Warp {
    glm::dvec2 unit_p;
    double length_p;
    double min_focus_proj;        // max(minCastersProj, minReceiversProj): where the focus interval starts
    Interval casters, receivers;  // step 4: the points along unitP
    double cos_gamma = 0.0;       // step 6: |V.xy|
    double coef = 0.0, epsilon_w = 0.0;
    double max_length_p = 0.0;      // step 5
    double optimal_length_p = 0.0;  // step 6: coef / cos γ
    bool clipped = false;           // step 7: lengthP = maxLengthP
};

// Steps 1 to 3: LightSpace with the points in it, the view vector V, its xy direction unitP.
void record_light_space(Trace* trace, const glm::dmat4& light_from_world, const LightSpacePoints& ls,
                        const glm::dvec3& ls_view);
// Steps 4 to 7: the intervals along unitP, maxLengthP, lengthP and its clipping.
void record_projection_vector(Trace* trace, const Warp& warp, const LightSpacePoints& ls, const glm::dvec3& ls_view);
// Steps 8 and 9: Projection (the w row) and ZRotation.
void record_ppls_factors(Trace* trace, const Warp& warp, const LightSpacePoints& ls, const glm::dmat4& projection,
                         const glm::dmat4& z_rotation);
// Step 10: the PPLS Transform, with the intersection body carried into PPLS.
void record_ppls_transform(Trace* trace, const glm::dmat4& ppls_from_light, const glm::dmat4& light_from_world,
                           const std::vector<glm::dvec3>& ws_body, double min_w);
// Steps 11 to 13: the PPLS points, their boxes and the FocusRegion between them.
void record_focus_region(Trace* trace, const ProjectedPoints& ppls_casters, const ProjectedPoints& ppls_receivers,
                         const Aabb& ppls_casters_box, const Aabb& ppls_receivers_box, const glm::dvec2& focus_min,
                         const glm::dvec2& focus_max);
// Steps 14 to 18: FocusRegionBasis, UnitCubeTransform, NormalizedSpace, the XPSM Transform, the bias.
void record_unit_cube(Trace* trace, const Aabb& focus, const glm::dmat4& ppls_from_uvz, const glm::dmat4& uvz_from_ppls,
                      const ShadowMap& map);

}  // namespace shadowlab::xpsm
