#include "render/shadow_map_pass.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <glm/gtc/type_ptr.hpp>
#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpaquePass.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLRenderer.h>
#include <vtkOpenGLState.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderState.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "lookup/kernel_taps.hpp"
#include "lookup/shadow_reader.hpp"
#include "raster/paraboloid_edges.hpp"
#include "render/program_uniforms.hpp"
#include "render/surface_shading.hpp"

namespace shadowlab {
namespace {

constexpr int kMaxMaps = ShadowMapPass::kMaxMaps;

// A map's tile in texels of the texture: its first texel and its size, rounded as texel_of rounds
// (maps/map_lookup.cpp): stage 1's scissor box, so that it writes exactly the texels stage 2 may read.
struct Tile {
    int x, y, width, height;
};

Tile tile_of(const ShadowMap& map, int resolution) {
    const auto texel = [resolution](double t) { return static_cast<int>(std::lround(t * resolution)); };
    const int x = texel(map.viewport.x), y = texel(map.viewport.y);
    return {x, y, texel(map.viewport.z) - x, texel(map.viewport.w) - y};
}

// The maps as the shaders' uniform arrays hold them: floats, matrices column-major, the entries
// past the last map zero.
struct MapArrays {
    int projection[kMaxMaps]{};
    glm::mat4 world_to_uvz[kMaxMaps]{};
    glm::vec3 paraboloid_centre[kMaxMaps]{};
    glm::mat4 paraboloid_frame[kMaxMaps]{};  // a mat3 in a mat4: vtkShaderProgram sets no mat3 arrays
    float paraboloid_near[kMaxMaps]{};
    float paraboloid_far[kMaxMaps]{};
    int cube_face[kMaxMaps]{};
    glm::vec4 viewport[kMaxMaps]{};
    glm::vec4 tile_texels[kMaxMaps]{};  // first and last texel (x, y, x, y) of the tile
};
// The arrays go to OpenGL as packed floats.
static_assert(sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(glm::vec4) == 4 * sizeof(float));
static_assert(sizeof(glm::mat4) == 16 * sizeof(float));

MapArrays map_arrays(const ShadowSetup& setup, int resolution) {
    MapArrays a;
    for (size_t i = 0; i < setup.maps.size(); ++i) {
        const ShadowMap& map = setup.maps[i];
        const Tile tile = tile_of(map, resolution);
        a.projection[i] = static_cast<int>(map.projection);
        a.world_to_uvz[i] = glm::mat4(map.world_to_uvz);
        a.paraboloid_centre[i] = glm::vec3(map.paraboloid.centre);
        a.paraboloid_frame[i] = glm::mat4(glm::mat3(map.paraboloid.frame_from_world));
        a.paraboloid_near[i] = static_cast<float>(map.paraboloid.near);
        a.paraboloid_far[i] = static_cast<float>(map.paraboloid.far);
        a.cube_face[i] = map.cube_face;
        a.viewport[i] = glm::vec4(map.viewport);
        a.tile_texels[i] = glm::vec4(tile.x, tile.y, tile.x + tile.width - 1, tile.y + tile.height - 1);
    }
    return a;
}

// Triangles as an actor whose vertices reach the shaders unchanged: stage 1 reads vertexMC as the
// point in the setup's coordinates.
vtkSmartPointer<vtkActor> triangles_actor(const WorldTriangles& triangles) {
    vtkNew<vtkPoints> points;
    for (const glm::dvec3& v : triangles.vertices) points->InsertNextPoint(v.x, v.y, v.z);
    vtkNew<vtkCellArray> cells;
    for (const std::array<int, 3>& t : triangles.triangles) {
        const vtkIdType corners[3] = {t[0], t[1], t[2]};
        cells->InsertNextCell(3, corners);
    }
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetPolys(cells);
    vtkNew<vtkOpenGLPolyDataMapper> mapper;
    mapper->SetInputData(data);
    mapper->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    return actor;
}

// Whether every uniform was found. The results come in as arguments, so that every uniform is set
// even when one is missing (&& would stop at it).
template <class... Found>
bool all_set(Found... found) {
    return (found && ...);
}

// Both stages: what map_homogeneous and hemisphere_side read. (The arrays are not const because
// SetUniformMatrix4x4v takes a float*.)
bool set_projection_uniforms(ProgramUniforms& program, MapArrays& maps) {
    return all_set(
        program.SetUniform1iv("shadowMapProjection", kMaxMaps, maps.projection),
        program.SetUniformMatrix4x4v("shadowMapWorldToUvz", kMaxMaps, glm::value_ptr(maps.world_to_uvz[0])),
        program.SetUniform3fv("shadowMapParaboloidCentre", kMaxMaps, glm::value_ptr(maps.paraboloid_centre[0])),
        program.SetUniformMatrix4x4v("shadowMapParaboloidFrame", kMaxMaps, glm::value_ptr(maps.paraboloid_frame[0])),
        program.SetUniform1fv("shadowMapParaboloidNear", kMaxMaps, maps.paraboloid_near),
        program.SetUniform1fv("shadowMapParaboloidFar", kMaxMaps, maps.paraboloid_far));
}

// Stage 2: the rest of select_map, look_up and texel_of.
bool set_lookup_uniforms(ProgramUniforms& program, MapArrays& maps, const ShadowSetup& setup) {
    const MapSelection& s = setup.selection;
    const size_t splits = std::min(s.split_depths.size(), setup.maps.size() + 1);  // as by_view_depth reads them
    float split_depths[kMaxMaps + 1]{};
    std::transform(s.split_depths.begin(), s.split_depths.begin() + splits, split_depths,
                   [](double depth) { return static_cast<float>(depth); });
    return all_set(program.SetUniformi("shadowMapCount", static_cast<int>(setup.maps.size())),
                   program.SetUniform1iv("shadowMapCubeFace", kMaxMaps, maps.cube_face),
                   program.SetUniform4fv("shadowMapViewport", kMaxMaps, glm::value_ptr(maps.viewport[0])),
                   program.SetUniform4fv("shadowMapTileTexels", kMaxMaps, glm::value_ptr(maps.tile_texels[0])),
                   program.SetUniformi("shadowSelectionRule", static_cast<int>(s.rule)),
                   program.SetUniform3f("shadowSelectionEye", glm::value_ptr(s.eye)),
                   program.SetUniform3f("shadowSelectionViewAxis", glm::value_ptr(s.view_axis)),
                   program.SetUniform1fv("shadowSelectionSplitDepths", kMaxMaps + 1, split_depths),
                   program.SetUniformi("shadowSelectionSplitCount", static_cast<int>(splits)),
                   program.SetUniformf("shadowSelectionBlendBand", static_cast<float>(s.blend_band)),
                   program.SetUniform3f("shadowSelectionCentre", glm::value_ptr(s.centre)));
}

// Stage 2: the overlay, its map palette and its ramp (render/map_overlay.hpp).
bool set_overlay_uniforms(ProgramUniforms& program, const std::vector<glm::vec3>& ramp) {
    static_assert(kMapPalette.size() == kMaxMaps, "one palette colour per map the pass holds");
    std::vector<glm::vec3> stops = ramp;
    stops.resize(ShadowMapPass::kMaxRampStops);
    return all_set(program.SetUniform3fv("shadowPalette", kMaxMaps, glm::value_ptr(kMapPalette[0])),
                   program.SetUniform3fv("shadowRamp", ShadowMapPass::kMaxRampStops, glm::value_ptr(stops[0])),
                   program.SetUniformi("shadowRampCount", static_cast<int>(ramp.size())));
}

// The taps the filter reads around the lookup (filter_taps, the CPU's own list and order), as the
// shaders hold them: (offset, weight).
std::vector<glm::vec3> packed_taps(const ShadowFilter& f) {
    std::vector<glm::vec3> packed;
    for (const KernelTap& tap : filter_taps(f))
        packed.emplace_back(glm::vec2(tap.offset), static_cast<float>(tap.weight));
    return packed;
}

// Stage 2: the filter, the bias and the light ShadowReader reads with, and the image pixel grid
// pixel_rotation numbers.
bool set_filter_uniforms(ProgramUniforms& program, const ShadowLookup& lookup, const Light& light,
                         std::vector<glm::vec3> taps, glm::ivec2 image_origin, int image_height) {
    const ShadowFilter& f = lookup.filter;
    const DepthBias& b = lookup.bias;
    const int tap_count = static_cast<int>(taps.size());
    taps.resize(ShadowMapPass::kMaxTaps);
    const auto real = [&program](const char* name, double value) {
        return program.SetUniformf(name, static_cast<float>(value));
    };
    return all_set(program.SetUniformi("shadowTapCount", tap_count),
                   program.SetUniform3fv("shadowTaps", ShadowMapPass::kMaxTaps, glm::value_ptr(taps[0])),
                   program.SetUniformi("shadowTapsTurn", f.kind == FilterKind::pcf && f.kernel == PcfKernel::poisson),
                   real("shadowFilterRadiusTexels", f.radius_texels), real("shadowFilterRadiusWorld", f.radius_world),
                   program.SetUniformi("shadowFilterKernelSize", f.kernel_size),
                   real("shadowMinVariance", f.min_variance), real("shadowBleedReduction", f.bleed_reduction),
                   real("shadowEvsmPositive", f.evsm_positive), real("shadowEvsmNegative", f.evsm_negative),
                   real("shadowBiasConstant", b.constant), real("shadowBiasSlopeScale", b.slope_scale),
                   real("shadowBiasNormalOffset", b.normal_offset),
                   program.SetUniformi("shadowLightDirectional", light.is_directional()),
                   program.SetUniform3f("shadowLightPosition", glm::value_ptr(light.position)),
                   real("shadowLightRadius", light.radius),
                   real("shadowLightTanAngularRadius", std::tan(glm::radians(light.angular_radius_deg))),
                   program.SetUniform2i("shadowImageOrigin", glm::value_ptr(image_origin)),
                   program.SetUniformi("shadowImageHeight", image_height));
}

template <class Value>
std::string glsl_int_constant(const char* name, Value value) {
    return "const int " + std::string(name) + " = " + std::to_string(static_cast<int>(value)) + ";\n";
}

// The constants the shaders share with C++, written from it so that neither side can drift: the
// arrays' sizes, the values of Projection, MapSelection::Rule, FilterKind and MapOverlay, the
// overlay's strength and range, and PCSS's search limit.
std::string glsl_constants() {
    const auto constant = [](const char* name, auto value) { return glsl_int_constant(name, value); };
    const auto real = [](const char* name, double value) {
        return "const float " + std::string(name) + " = " + std::to_string(value) + ";\n";
    };
    using Rule = MapSelection::Rule;
    return constant("shadowMaxMaps", kMaxMaps) + constant("shadowMaxRampStops", ShadowMapPass::kMaxRampStops) +
           constant("shadowMaxTaps", ShadowMapPass::kMaxTaps) + constant("shadowFilterVsm", FilterKind::vsm) +
           constant("shadowFilterEvsm", FilterKind::evsm) + constant("shadowFilterPcss", FilterKind::pcss) +
           real("shadowMaxSearchTexels", ShadowReader::kMaxSearchTexels) +
           constant("shadowParaboloid", Projection::paraboloid) + constant("shadowRuleOnly", Rule::only) +
           constant("shadowRuleViewDepth", Rule::view_depth) + constant("shadowRuleTileBounds", Rule::tile_bounds) +
           constant("shadowRuleCubeFace", Rule::cube_face) + constant("shadowRuleHemisphere", Rule::hemisphere) +
           constant("shadowOverlayNone", MapOverlay::none) +
           constant("shadowOverlayCascadeIndex", MapOverlay::cascade_index) +
           real("shadowOverlayStrength", kOverlayStrength) + real("shadowTexelsLog2Range", kTexelsLog2Range);
}

// Stage 2's switches: what picks one branch for every fragment alike, the filter, whether the
// receiver's plane slopes its depth, and the overlay (none on a grey-level output). One general
// program reads them as uniforms. The common case, a hard lookup with neither receiver plane nor
// overlay (the window's default), has a program of its own with them compiled in as constants, so
// that the compiler drops the branches not taken, which a rasterizer on the CPU (llvmpipe) would
// otherwise run under a mask for every fragment: the Camera view of the default town renders in
// 35 ms instead of 48 (bench/view_drawing_bench.cpp). Only that case: a program compiles on the
// GUI thread the first time it is drawn, and under llvmpipe, before Mesa's shader cache on disk
// holds it, this one takes 0.14 s, the general one 1.6 s and one specialized for PCSS 0.9 s: each
// specialization more would be one pause more for a user trying the filters.
struct Stage2Switches {
    FilterKind filter;
    bool receiver_plane;
    MapOverlay overlay;

    bool compiled_in() const { return filter == FilterKind::hard && !receiver_plane && overlay == MapOverlay::none; }
    std::string declarations() const {
        const auto declared = [this](const char* name, int value) {
            return compiled_in() ? glsl_int_constant(name, value) : "uniform int " + std::string(name) + ";\n";
        };
        return declared("shadowFilterKind", static_cast<int>(filter)) +
               declared("shadowBiasReceiverPlane", receiver_plane) +
               declared("shadowOverlay", static_cast<int>(overlay));
    }
    bool set(ProgramUniforms& program) const {
        return compiled_in() || all_set(program.SetUniformi("shadowFilterKind", static_cast<int>(filter)),
                                        program.SetUniformi("shadowBiasReceiverPlane", receiver_plane),
                                        program.SetUniformi("shadowOverlay", static_cast<int>(overlay)));
    }
};

Stage2Switches stage2_switches(const ShadowLookup& lookup, ShadowMapPass::Output output, MapOverlay overlay) {
    return {.filter = lookup.filter.kind,
            .receiver_plane = lookup.bias.receiver_plane,
            .overlay = output == ShadowMapPass::Output::shaded ? overlay : MapOverlay::none};
}

// Both stages: each map's point before the division, map_homogeneous and hemisphere_side
// (maps/map_lookup.cpp) line by line. A cube face is a linear map like any other.
constexpr const char* kProjectionDeclarations = R"(
uniform int shadowMapProjection[shadowMaxMaps];
uniform mat4 shadowMapWorldToUvz[shadowMaxMaps];
uniform vec3 shadowMapParaboloidCentre[shadowMaxMaps];
uniform mat4 shadowMapParaboloidFrame[shadowMaxMaps];  // frame_from_world in the upper-left 3x3
uniform float shadowMapParaboloidNear[shadowMaxMaps];
uniform float shadowMapParaboloidFar[shadowMaxMaps];
vec3 shadowInParaboloidFrame(int i, vec3 p) {
  return mat3(shadowMapParaboloidFrame[i]) * (p - shadowMapParaboloidCentre[i]);
}
vec4 shadowParaboloidHomogeneous(int i, vec3 p) {
  vec3 q = shadowInParaboloidFrame(i, p);
  float dist = length(q);
  if (!(dist > 0.0)) return vec4(0.0);
  vec3 d = q / dist;
  float denominator = 1.0 + d.z;
  if (!(denominator > 1e-12)) return vec4(0.0);  // straight behind: the map's singular point
  vec2 uv = (d.xy / denominator + 1.0) / 2.0;
  float nearD = shadowMapParaboloidNear[i], farD = shadowMapParaboloidFar[i];
  return vec4(uv, (dist - nearD) / (farD - nearD), 1.0);
}
vec4 shadowHomogeneous(int i, vec3 p) {
  if (shadowMapProjection[i] == shadowParaboloid) return shadowParaboloidHomogeneous(i, p);
  return shadowMapWorldToUvz[i] * vec4(p, 1.0);
}
float shadowHemisphereSide(int i, vec3 p) {
  return shadowMapProjection[i] == shadowParaboloid ? shadowInParaboloidFrame(i, p).z : 1.0;
}
)";

// Stage 1: the drawn map and its tile (u0, v0, u1, v1) in the texture.
constexpr const char* kDepthDeclarations = R"(uniform int shadowDrawnMap;
uniform vec4 shadowDrawnViewport;
)";

// Stage 1, the viewport on the whole texture: the drawn map's (u, v) placed in its tile as
// texture_uv places it, before the division and unrounded (a viewport on the tile would round its
// edges to whole texels and shift the map against the CPU rasterizer's by up to a texel), then in
// OpenGL clip space (x' = 2x - w, the same for y and z); and the distance to its hemisphere plane,
// which clips a paraboloid's casters where the CPU rasterizer cuts them (GL_CLIP_DISTANCE0 is on for
// paraboloids only).
constexpr const char* kDepthPosition = R"(vec4 shadowH = shadowHomogeneous(shadowDrawnMap, vertexMC.xyz);
  vec4 shadowTile = shadowDrawnViewport;
  vec2 shadowInTexture = shadowTile.xy * shadowH.w + shadowH.xy * (shadowTile.zw - shadowTile.xy);
  gl_Position = vec4(2.0 * shadowInTexture - shadowH.w, 2.0 * shadowH.z - shadowH.w, shadowH.w);
  gl_ClipDistance[0] = shadowHemisphereSide(shadowDrawnMap, vertexMC.xyz);)";

// Stage 2, after the projections: select_map, blend_of, texel_of, uv_derivative, depth_slope and
// distance_back_to_depth (maps/map_lookup.cpp) line by line.
constexpr const char* kLookupDeclarations = R"(
uniform int shadowMapCount;
uniform int shadowMapCubeFace[shadowMaxMaps];
uniform vec4 shadowMapViewport[shadowMaxMaps];    // (u0, v0, u1, v1): the tile in the texture
uniform vec4 shadowMapTileTexels[shadowMaxMaps];  // first and last texel (x, y, x, y) of the tile
uniform float shadowMapZBiasScale[shadowMaxMaps];
uniform int shadowSelectionRule;
uniform vec3 shadowSelectionEye;
uniform vec3 shadowSelectionViewAxis;
uniform float shadowSelectionSplitDepths[shadowMaxMaps + 1];
uniform int shadowSelectionSplitCount;
uniform float shadowSelectionBlendBand;
uniform vec3 shadowSelectionCentre;
uniform sampler2D shadowDepth;
uniform int shadowResolution;
uniform int shadowLitThreshold;  // 1: the lit mask, the visibility thresholded at one half
bool shadowInUnitRange(float t) { return t >= 0.0 && t <= 1.0; }  // false for NaN
bool shadowOnMap(vec4 h) { return h.w > 0.0 && shadowInUnitRange(h.x / h.w) && shadowInUnitRange(h.y / h.w); }
// 0..5 for +x, -x, +y, -y, +z, -z: the major axis of r (x, then y, on ties) and its sign.
int shadowMajorAxisFace(vec3 r) {
  vec3 a = abs(r);
  int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
  return 2 * axis + (r[axis] < 0.0 ? 1 : 0);
}
float shadowViewDepth(vec3 p) { return dot(p - shadowSelectionEye, shadowSelectionViewAxis); }
// Map i serves view depths in [split i, split i + 1), the last split included.
int shadowByViewDepth(vec3 p) {
  float depth = shadowViewDepth(p);
  for (int i = 0; i + 1 < shadowSelectionSplitCount; ++i)
    if (depth >= shadowSelectionSplitDepths[i] &&
        (depth < shadowSelectionSplitDepths[i + 1] ||
         (i + 2 == shadowSelectionSplitCount && depth == shadowSelectionSplitDepths[i + 1])))
      return i;
  return -1;
}
// Whether map i holds p under the rules that take the first map holding it.
bool shadowHolds(int i, vec3 p) {
  if (shadowSelectionRule == shadowRuleTileBounds) return shadowOnMap(shadowHomogeneous(i, p));
  if (shadowSelectionRule == shadowRuleCubeFace)
    return shadowMapCubeFace[i] == shadowMajorAxisFace(p - shadowSelectionCentre);
  return shadowSelectionRule == shadowRuleHemisphere && shadowHemisphereSide(i, p) >= 0.0;
}
int shadowSelectMap(vec3 p) {
  if (shadowMapCount == 0) return -1;
  if (shadowSelectionRule == shadowRuleOnly) return 0;
  if (shadowSelectionRule == shadowRuleViewDepth) return shadowByViewDepth(p);
  for (int i = 0; i < shadowMapCount; ++i)
    if (shadowHolds(i, p)) return i;
  return -1;
}
// blend_of: map i + 1's share at p, rising from 0 to 1 over the last blend band of split i; none
// after the last split or under the other rules.
float shadowBlendWeight(int i, vec3 p) {
  if (shadowSelectionRule != shadowRuleViewDepth || !(shadowSelectionBlendBand > 0.0) ||
      !(i >= 0 && i + 2 < shadowSelectionSplitCount))
    return 0.0;
  float splitEnd = shadowSelectionSplitDepths[i + 1];
  float band = shadowSelectionBlendBand * (splitEnd - shadowSelectionSplitDepths[i]);
  return clamp((shadowViewDepth(p) - (splitEnd - band)) / band, 0.0, 1.0);
}
// The texel map i's (u, v) reads: the nearest, kept in the map's tile.
ivec2 shadowTexelOf(int i, vec2 uv) {
  vec4 tile = shadowMapViewport[i];
  vec2 t = (tile.xy + uv * (tile.zw - tile.xy)) * float(shadowResolution);
  return ivec2(clamp(floor(t), shadowMapTileTexels[i].xy, shadowMapTileTexels[i].zw));
}
float shadowTileResolution(int i) {
  return (shadowMapViewport[i].z - shadowMapViewport[i].x) * float(shadowResolution);
}
vec2 shadowUv(int i, vec3 p) { vec4 h = shadowHomogeneous(i, p); return h.xy / h.w; }
// uv_derivative: the quotient rule on a linear map's rows; a central difference for a paraboloid.
vec2 shadowUvDerivative(int i, vec3 p, vec3 direction) {
  if (shadowMapProjection[i] == shadowParaboloid) {
    float step = 1e-3 * length(p - shadowMapParaboloidCentre[i]);  // float32: a coarser step than the CPU's
    return (shadowUv(i, p + step * direction) - shadowUv(i, p - step * direction)) / (2.0 * step);
  }
  vec4 h = shadowMapWorldToUvz[i] * vec4(p, 1.0), dh = shadowMapWorldToUvz[i] * vec4(direction, 0.0);
  return (dh.xy * h.w - h.xy * dh.w) / (h.w * h.w);
}
// ∂d/∂t: the depth after the division per world unit along l at p.
float shadowDepthSlope(int i, vec3 l, vec3 p) {
  if (shadowMapProjection[i] == shadowParaboloid)  // d = (|q| - near) / (far - near)
    return dot(normalize(shadowInParaboloidFrame(i, p)), mat3(shadowMapParaboloidFrame[i]) * l) /
           (shadowMapParaboloidFar[i] - shadowMapParaboloidNear[i]);
  vec4 h = shadowMapWorldToUvz[i] * vec4(p, 1.0), dh = shadowMapWorldToUvz[i] * vec4(l, 0.0);
  return (dh.z * h.w - h.z * dh.w) / (h.w * h.w);  // the quotient rule on d_pre / w
}
// The shaders' stand-in for the CPU's infinities (float32 holds up to 3.4e38).
const float shadowUnbounded = 1e30;
// distance_back_to_depth: how far from p back toward the light the depth falls to `depth`;
// unbounded where the ray never reaches it.
float shadowDistanceBackToDepth(int i, vec3 l, vec3 p, float depth) {
  if (shadowMapProjection[i] == shadowParaboloid) {  // back along a radial ray, d falls by 1 / (far - near) per unit
    vec4 h = shadowParaboloidHomogeneous(i, p);
    return (h.z - depth) * (shadowMapParaboloidFar[i] - shadowMapParaboloidNear[i]);
  }
  // At p - s l the map holds (h.z - s dh.z) / (h.w - s dh.w); set it to `depth` and solve for s.
  vec4 h = shadowMapWorldToUvz[i] * vec4(p, 1.0), dh = shadowMapWorldToUvz[i] * vec4(l, 0.0);
  float s = (h.z - depth * h.w) / (dh.z - depth * dh.w);
  return !isinf(s) && !isnan(s) && s >= 0.0 ? s : shadowUnbounded;
}
)";

// Stage 2, the depth biases (lookup/depth_bias.cpp) under map i: the texel's world size across the
// light, the slope-scaled bias and the receiver's plane, each a function of the CPU's name.
constexpr const char* kBiasDeclarations = R"(
uniform float shadowBiasConstant;      // world units along the light
uniform float shadowBiasSlopeScale;    // times the slope-scaled bias
uniform float shadowBiasNormalOffset;  // texels
// across(): two unit directions perpendicular to l and to each other.
void shadowAcross(vec3 l, out vec3 a, out vec3 b) {
  a = normalize(cross(l, abs(l.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  b = cross(l, a);
}
// smallest_singular_value (math/singular_values.hpp) of the 2x2 matrix (j0 j1), as σ_min² = 2 det² /
// (f + √(f² − 4 det²)): the same value without the float32 cancellation of (f − √(f² − 4 det²)) / 2
// where the map stretches one way far more than the other.
float shadowSmallestSingularValue(vec2 j0, vec2 j1) {
  float f = dot(j0, j0) + dot(j1, j1), det = j0.x * j1.y - j0.y * j1.x;
  float larger = f + sqrt(max(0.0, f * f - 4.0 * det * det));
  return larger > 0.0 ? sqrt(2.0 * det * det / larger) : 0.0;
}
// texel_world_size: 1 / (texels σ_min(J)), J = d(u, v) per world unit across the light. 0 where the
// CPU's is infinite (the map sees no area there): every use below then takes no offset, no
// slope-scaled bias and no radius, as the CPU's finite_or does.
float shadowTexelWorldSize(int i, float texels, vec3 l, vec3 p) {
  vec3 a, b;
  shadowAcross(l, a, b);
  float sigmaMin = shadowSmallestSingularValue(shadowUvDerivative(i, p, a), shadowUvDerivative(i, p, b));
  return sigmaMin > 0.0 ? 1.0 / (texels * sigmaMin) : 0.0;
}
// A world length across the light at a texel's world size, in the map's texels (0 for no size).
float shadowInTexels(float worldLength, float texelWorld) { return texelWorld > 0.0 ? worldLength / texelWorld : 0.0; }
// slope_scaled_bias: a texel's world width times 1 + tan θ (clamped to 10).
float shadowSlopeScaledBias(float texelWorld, float cosTheta) {
  float tanTheta = min(10.0, sqrt(max(0.0, 1.0 - cosTheta * cosTheta)) / max(cosTheta, 1e-6));
  return texelWorld * (1.0 + tanTheta);
}
// receiver_plane_gradient: ∂d/∂(u, v) on the plane through p with normal n, g = (∂d/∂s₁, ∂d/∂s₂) J⁻¹
// for two directions s₁, s₂ in the plane; 0 where the map sees the plane edge-on.
vec2 shadowReceiverPlaneGradient(int i, vec3 p, vec3 n) {
  vec3 s1, s2;
  shadowAcross(n, s1, s2);
  mat2 j = mat2(shadowUvDerivative(i, p, s1), shadowUvDerivative(i, p, s2));
  vec2 along = vec2(shadowDepthSlope(i, s1, p), shadowDepthSlope(i, s2, p));
  if (!(abs(determinant(j)) > 1e-12 * (dot(j[0], j[0]) + dot(j[1], j[1])))) return vec2(0.0);
  return along * inverse(j);  // a row vector times J⁻¹
}
)";

// Stage 2, the filters: ShadowReader (lookup/shadow_reader.cpp) step by step, its functions under
// the same names: under, lit_share, soft_shadow, chebyshev_visibility, map_visibility. The taps are
// the CPU's lists (filter_taps, packed_taps); the Poisson disk turns by pixel_rotation (lookup/kernel_taps.cpp) of
// the fragment's image pixel. VSM and EVSM read the blurred moments (lookup/moment_map.cpp) as
// sample_moments does, bilinear between four texels, each texel's box sum taken from the depth
// texture on the spot: the CPU's prefiltered texture, without a second render target.
constexpr const char* kFilterDeclarations = R"(
uniform int shadowTapCount;
uniform vec3 shadowTaps[shadowMaxTaps];  // (offset in the kernel's radius, weight)
uniform int shadowTapsTurn;              // pcf's Poisson disk turns per pixel
uniform float shadowFilterRadiusTexels;
uniform float shadowFilterRadiusWorld;   // > 0: overrides the radius in texels
uniform int shadowFilterKernelSize;      // vsm, evsm: the blur's side
uniform float shadowMinVariance;
uniform float shadowBleedReduction;
uniform float shadowEvsmPositive, shadowEvsmNegative;
uniform int shadowLightDirectional;
uniform vec3 shadowLightPosition;
uniform float shadowLightRadius;
uniform float shadowLightTanAngularRadius;
uniform ivec2 shadowImageOrigin;  // the renderer's corner in the window, and its height: the image's pixels
uniform int shadowImageHeight;
// hash_pixel: Wellons' lowbias32; GLSL's uint arithmetic wraps as C++'s does.
uint shadowHashPixel(uint x, uint y) {
  uint h = x * 1664525u ^ y * 22695477u;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}
// pixel_rotation of the fragment's pixel, counted as the CPU's images count them: row 0 at the top.
float shadowPixelRotation() {
  ivec2 pixel = ivec2(floor(gl_FragCoord.xy)) - shadowImageOrigin;
  pixel.y = shadowImageHeight - 1 - pixel.y;
  return 6.283185307179586 * (float(shadowHashPixel(uint(pixel.x), uint(pixel.y))) / 4294967296.0);
}
vec2 shadowRotated(vec2 v, float c, float s) { return vec2(c * v.x - s * v.y, s * v.x + c * v.y); }
// texel_centre_uv: the centre of a texture texel in map i's (u, v).
vec2 shadowTexelCentreUv(int i, ivec2 texel) {
  vec4 tile = shadowMapViewport[i];
  return ((vec2(texel) + 0.5) / float(shadowResolution) - tile.xy) / (tile.zw - tile.xy);
}
// biased_depth: the map's depth of p moved `bias` world units back toward the light; where that
// reaches the light or the map's centre, below every stored depth (lit by any texel).
float shadowBiasedDepth(int i, vec3 p, vec3 l, float bias) {
  vec4 h = shadowHomogeneous(i, p - bias * l);
  return h.w > 0.0 && shadowHemisphereSide(i, p - bias * l) >= 0.0 ? h.z / h.w : -shadowUnbounded;
}
// The receiver under one map (MapReceiver).
struct ShadowMapReceiver {
  vec3 position;        // the point looked up: the receiver, moved by the normal offset
  vec3 lightDirection;  // the way light travels there
  float texels;         // across the map's tile
  vec2 uv;
  float depth;          // the point's depth, less the bias in depth units
  vec2 planeGradient;   // receiver plane: ∂d/∂(u, v); 0 when off
  float texelWorld;     // a texel's world width across the light there (0: no size)
};
// under: the normal offset moves the point, then the constant and slope-scaled biases (world lengths)
// move it nearer the light along the light ray for its depth alone. False off the map.
bool shadowUnder(int i, vec3 position, vec3 normal, out ShadowMapReceiver m) {
  m.texels = shadowTileResolution(i);
  vec3 l = surfaceAlongLight(position);
  m.lightDirection = l;
  m.texelWorld = shadowTexelWorldSize(i, m.texels, l, position);
  vec3 p = position + normal * (shadowBiasNormalOffset * m.texelWorld);
  m.position = p;
  vec4 h = shadowHomogeneous(i, p);
  if (!shadowOnMap(h)) return false;
  m.uv = h.xy / h.w;
  float slopeScaled =
      shadowBiasSlopeScale > 0.0 ? shadowBiasSlopeScale * shadowSlopeScaledBias(m.texelWorld, dot(normal, -l)) : 0.0;
  m.depth = shadowBiasedDepth(i, p, l, shadowBiasConstant + slopeScaled);
  m.planeGradient = shadowBiasReceiverPlane == 1 ? shadowReceiverPlaneGradient(i, p, normal) : vec2(0.0);
  return true;
}
// lit_share: the weighted share of taps the receiver passes, each reading its nearest texel (kept in
// the tile) and comparing the receiver's depth there, on its plane when the receiver-plane bias is on.
float shadowLitShare(int i, ShadowMapReceiver m, float radiusTexels, float rotation) {
  float c = cos(rotation), s = sin(rotation);
  float lit = 0.0;
  for (int k = 0; k < shadowTapCount; ++k) {
    ivec2 texel = shadowTexelOf(i, m.uv + shadowRotated(shadowTaps[k].xy, c, s) * (radiusTexels / m.texels));
    float receiver = m.depth + dot(m.planeGradient, shadowTexelCentreUv(i, texel) - m.uv);
    if (receiver <= texelFetch(shadowDepth, texel, 0).r) lit += shadowTaps[k].z;
  }
  return min(lit, 1.0);  // the weights' rounding
}
// penumbra_width (lookup/pcss.cpp) at receiver point p for a blocker delta before it: 2 Δ tan α for
// the sun, (L − (L − Δ)) 2R / (L − Δ) for a sphere light; a blocker at the light: unbounded.
float shadowPenumbraWidth(vec3 p, float delta) {
  if (shadowLightDirectional == 1) return 2.0 * delta * shadowLightTanAngularRadius;
  float receiverDistance = distance(p, shadowLightPosition);
  float blockerDistance = receiverDistance - delta;
  if (!(blockerDistance > 0.0)) return shadowUnbounded;
  return (receiverDistance - blockerDistance) * 2.0 * shadowLightRadius / blockerDistance;
}
// soft_shadow: PCSS's three steps over the Poisson disk.
float shadowSoftShadow(int i, ShadowMapReceiver m, float rotation) {
  // Step 1, the blocker search over the light's footprint back to the map's near plane (d = 0), at
  // most kMaxSearchTexels (blocker_search_radius: half the penumbra).
  float toNearPlane = shadowDistanceBackToDepth(i, m.lightDirection, m.position, 0.0);
  float search =
      min(shadowInTexels(shadowPenumbraWidth(m.position, toNearPlane) / 2.0, m.texelWorld), shadowMaxSearchTexels);
  float c = cos(rotation), s = sin(rotation);
  float blockerDepth = 0.0;
  int blockers = 0;
  for (int k = 0; k < shadowTapCount; ++k) {
    ivec2 texel = shadowTexelOf(i, m.uv + shadowRotated(shadowTaps[k].xy, c, s) * (search / m.texels));
    float stored = texelFetch(shadowDepth, texel, 0).r;
    if (stored < m.depth) {
      blockerDepth += stored;
      ++blockers;
    }
  }
  if (blockers == 0) return 1.0;  // nothing between the receiver and the light
  blockerDepth /= float(blockers);
  // Step 2, the penumbra the average blocker casts; step 3, PCF over it (never wider than the search).
  float blockerDistance = shadowDistanceBackToDepth(i, m.lightDirection, m.position, blockerDepth);
  float radius = shadowInTexels(shadowPenumbraWidth(m.position, blockerDistance) / 2.0, m.texelWorld);
  return shadowLitShare(i, m, min(radius, search), rotation);
}
// evsm_positive_warp and evsm_negative_warp (lookup/chebyshev.hpp): e^{c⁺d}, −e^{−c⁻d}.
vec2 shadowEvsmWarps(float depth) { return vec2(exp(shadowEvsmPositive * depth), -exp(-shadowEvsmNegative * depth)); }
// moments_of: vsm (d, d², 0, 0); evsm (e⁺, (e⁺)², e⁻, (e⁻)²).
vec4 shadowMomentsOf(float depth) {
  if (shadowFilterKind == shadowFilterVsm) return vec4(depth, depth * depth, 0.0, 0.0);
  vec2 e = shadowEvsmWarps(depth);
  return vec4(e.x, e.x * e.x, e.y, e.y * e.y);
}
// blurred_moments at one texel: the N×N box (N/2 texels back, N − 1 − N/2 ahead, each axis clamped
// to the tile), what its two separable passes leave there.
vec4 shadowBlurredMoments(int i, ivec2 texel) {
  int side = shadowFilterKernelSize, before = side / 2, after = side - 1 - before;
  ivec2 first = ivec2(shadowMapTileTexels[i].xy), last = ivec2(shadowMapTileTexels[i].zw);
  vec4 sum = vec4(0.0);
  for (int dy = -before; dy <= after; ++dy)
    for (int dx = -before; dx <= after; ++dx)
      sum += shadowMomentsOf(texelFetch(shadowDepth, clamp(texel + ivec2(dx, dy), first, last), 0).r);
  return sum / float(side * side);
}
// sample_moments: bilinear between the four nearest texel centres, kept in the tile.
vec4 shadowSampleMoments(int i, vec2 uv) {
  vec4 tile = shadowMapViewport[i];
  vec2 t = (tile.xy + uv * (tile.zw - tile.xy)) * float(shadowResolution) - 0.5;  // texel centres at whole numbers
  vec2 base = floor(t), f = t - base;
  ivec2 first = ivec2(shadowMapTileTexels[i].xy), last = ivec2(shadowMapTileTexels[i].zw), b = ivec2(base);
  vec4 m00 = shadowBlurredMoments(i, clamp(b, first, last));
  vec4 m10 = shadowBlurredMoments(i, clamp(b + ivec2(1, 0), first, last));
  vec4 m01 = shadowBlurredMoments(i, clamp(b + ivec2(0, 1), first, last));
  vec4 m11 = shadowBlurredMoments(i, clamp(b + ivec2(1, 1), first, last));
  return mix(mix(m00, m10, f.x), mix(m01, m11, f.x), f.y);
}
// chebyshev_upper_bound and reduce_light_bleeding (lookup/chebyshev.hpp).
float shadowChebyshevUpperBound(float mean, float variance, float t) {
  if (t <= mean) return 1.0;
  float d = t - mean;
  return variance / (variance + d * d);
}
float shadowReduceLightBleeding(float pMax, float amount) {
  if (!(amount > 0.0)) return pMax;
  return clamp((pMax - amount) / (1.0 - amount), 0.0, 1.0);
}
// chebyshev_visibility: Chebyshev's bound at the receiver's depth; EVSM's variance floors scaled by
// each warp's slope, (c e^{cd})², so that they are the same in depth units.
float shadowChebyshevVisibility(int i, ShadowMapReceiver m) {
  vec4 mo = shadowSampleMoments(i, m.uv);
  float p;
  if (shadowFilterKind == shadowFilterVsm) {
    p = shadowChebyshevUpperBound(mo.x, max(mo.y - mo.x * mo.x, shadowMinVariance), m.depth);
  } else {
    vec2 e = shadowEvsmWarps(m.depth);
    vec2 slopes = vec2(shadowEvsmPositive, shadowEvsmNegative) * e;
    vec2 floors = shadowMinVariance * slopes * slopes;
    p = min(shadowChebyshevUpperBound(mo.x, max(mo.y - mo.x * mo.x, floors.x), e.x),
            shadowChebyshevUpperBound(mo.z, max(mo.w - mo.z * mo.z, floors.y), e.y));
  }
  return shadowReduceLightBleeding(p, shadowBleedReduction);
}
// map_visibility: one map's share of the light at the receiver; off the map, lit. Hard reads its one
// tap at the centre, which no radius moves.
float shadowMapVisibility(int i, vec3 position, vec3 normal, float rotation) {
  ShadowMapReceiver m;
  if (!shadowUnder(i, position, normal, m)) return 1.0;
  if (shadowFilterKind == shadowFilterPcss) return shadowSoftShadow(i, m, rotation);
  if (shadowFilterKind == shadowFilterVsm || shadowFilterKind == shadowFilterEvsm)
    return shadowChebyshevVisibility(i, m);
  float radius = shadowFilterRadiusWorld > 0.0 ? shadowInTexels(shadowFilterRadiusWorld, m.texelWorld)
                                               : shadowFilterRadiusTexels;
  return shadowLitShare(i, m, radius, shadowTapsTurn == 1 ? rotation : 0.0);
}
)";

// Stage 2, the overlay: the selected map's palette colour (in a band both, crossfaded by the
// weight), or its texels per pixel on the ramp: the pixel's footprint in the map's texels as OpenGL
// sizes it to pick a mip level (the scale factor ρ, §8.14 of the 4.5 core profile): the longer of
// d(u, v)/dx and d(u, v)/dy across the screen, in the tile's texels.
constexpr const char* kOverlayDeclarations = R"(
uniform vec3 shadowPalette[shadowMaxMaps];
uniform vec3 shadowRamp[shadowMaxRampStops];
uniform int shadowRampCount;
vec3 shadowRampColour(float t) {
  float s = clamp(t, 0.0, 1.0) * float(shadowRampCount - 1);
  int k = min(int(s), shadowRampCount - 2);
  return mix(shadowRamp[k], shadowRamp[k + 1], s - float(k));
}
float shadowTexelsPerPixel(int i, vec3 p, vec3 dpdx, vec3 dpdy) {
  return shadowTileResolution(i) * max(length(shadowUvDerivative(i, p, dpdx)), length(shadowUvDerivative(i, p, dpdy)));
}
vec4 shadowOverlaid(vec4 colour, int i, float w, vec3 p, vec3 dpdx, vec3 dpdy) {
  if (shadowOverlay == shadowOverlayNone || i < 0) return colour;
  vec3 tint;
  if (shadowOverlay == shadowOverlayCascadeIndex)
    tint = w > 0.0 ? mix(shadowPalette[i], shadowPalette[i + 1], w) : shadowPalette[i];
  else  // texels_ramp_position
    tint = shadowRampColour((shadowTexelsLog2Range - log2(max(shadowTexelsPerPixel(i, p, dpdx, dpdy), 1e-6))) /
                            (2.0 * shadowTexelsLog2Range));
  return vec4(mix(colour.rgb, tint, shadowOverlayStrength), colour.a);
}
)";

// The lookup, after VTK's lighting: ShadowReader::visibility, the selected map's visibility
// crossfaded with the next map's inside a blend band; no map counts as lit. The shading is linear in
// `lit`, so that shading with the visibility mixes the two maps' shadings by the weight and shades a
// penumbra by the share of light it sees; the lit mask thresholds the visibility at one half, as the
// CPU's verdicts do; the visibility output writes it as a grey level. The seen normal and the
// position's screen derivatives are only defined in uniform control flow: taken before the lookup
// branches. The colour is the shared surface shading's, with the overlay over it.
constexpr const char* kLookup = R"(//VTK::Light::Impl
  {
    vec3 p = surfaceWorldVSOutput.xyz;
    vec3 n = surfaceSeenNormal(p);
    vec3 dpdx = dFdx(p), dpdy = dFdy(p);
    int i = shadowSelectMap(p);
    float w = shadowBlendWeight(i, p);
    float rotation = shadowPixelRotation();
    float visibility = 1.0;
    if (i >= 0)
      visibility = w > 0.0 ? mix(shadowMapVisibility(i, p, n, rotation), shadowMapVisibility(i + 1, p, n, rotation), w)
                           : shadowMapVisibility(i, p, n, rotation);
    float lit = shadowLitThreshold == 1 ? (visibility < 0.5 ? 0.0 : 1.0) : visibility;
    vec4 colour = surfaceColour(ambientColor, diffuseColor, opacity, p, n, lit);
    gl_FragData[0] = shadowOverlaid(colour, i, w, p, dpdx, dpdy);
  }
)";

}  // namespace

vtkStandardNewMacro(ShadowMapPass);

ShadowMapPass::ShadowMapPass() : depth_pass_(vtkSmartPointer<vtkOpaquePass>::New()) {}

ShadowMapPass::~ShadowMapPass() = default;

void ShadowMapPass::SetSetup(const ShadowSetup& setup, int resolution) {
    if (setup.maps.size() > static_cast<size_t>(kMaxMaps))
        throw std::invalid_argument("ShadowMapPass: the setup has " + std::to_string(setup.maps.size()) +
                                    " maps; the GPU pass holds at most " + std::to_string(kMaxMaps));
    setup_ = setup;
    resolution_ = resolution;
    split_casters_per_map();
    Modified();
}

void ShadowMapPass::SetLookup(const ShadowLookup& lookup, const Light& light, const glm::dvec3& eye) {
    std::vector<glm::vec3> taps = packed_taps(lookup.filter);
    if (taps.size() > static_cast<size_t>(kMaxTaps))
        throw std::invalid_argument("ShadowMapPass: a filter of " + std::to_string(taps.size()) +
                                    " taps; the GPU pass holds at most " + std::to_string(kMaxTaps));
    lookup_ = lookup;
    light_ = light;
    taps_ = std::move(taps);
    const glm::dvec4 shaded_by =
        light.is_directional() ? glm::dvec4(light.direction, 0.0) : glm::dvec4(light.position, 1.0);
    frame_ = {.light = glm::vec4(shaded_by), .eye = glm::vec3(eye)};
    Modified();
}

void ShadowMapPass::SetCasters(const std::vector<vtkProp*>& casters) {
    casters_ = casters;
    Modified();
}

void ShadowMapPass::SetCasterTriangles(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object) {
    caster_triangles_ = triangles;
    casts_per_object_ = casts_per_object;
    split_casters_per_map();
    Modified();
}

// Once per setup, resolution and casters, not per frame: the split depends on nothing else.
void ShadowMapPass::split_casters_per_map() {
    split_casters_.assign(setup_.maps.size(), nullptr);
    if (caster_triangles_.triangles.empty()) return;
    for (size_t i = 0; i < setup_.maps.size(); ++i)
        if (splits_casters(setup_.maps[i]))
            split_casters_[i] =
                triangles_actor(split_casters(caster_triangles_, casts_per_object_, setup_.maps[i], resolution_));
}

void ShadowMapPass::SetShadePass(vtkRenderPass* shade) {
    shade_ = shade;
    Modified();
}

void ShadowMapPass::SetOutput(Output output) {
    output_ = output;
    Modified();
}

void ShadowMapPass::SetOverlay(MapOverlay overlay, const std::vector<glm::vec3>& ramp) {
    if (ramp.size() < 2 || ramp.size() > static_cast<size_t>(kMaxRampStops))
        throw std::invalid_argument("ShadowMapPass: an overlay ramp of " + std::to_string(ramp.size()) +
                                    " colours; it takes 2 to " + std::to_string(kMaxRampStops));
    overlay_ = overlay;
    ramp_ = ramp;
    Modified();
}

void ShadowMapPass::enter(Stage stage) {
    stage_ = stage;
    stage_time_.Modified();  // the mappers rebuild their shaders (from VTK's shader cache)
}

void ShadowMapPass::Render(const vtkRenderState* s) {
    NumberOfRenderedProps = 0;
    auto* window = static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
    prepare_targets(window);
    render_depth(s, window);
    render_shaded(s);
}

void ShadowMapPass::prepare_targets(vtkOpenGLRenderWindow* window) {
    if (depth_ && depth_->GetWidth() == static_cast<unsigned>(resolution_) && depth_->GetContext() == window) return;
    ReleaseGraphicsResources(window);
    depth_ = vtkSmartPointer<vtkTextureObject>::New();
    depth_->SetContext(window);
    depth_->SetMinificationFilter(vtkTextureObject::Nearest);
    depth_->SetMagnificationFilter(vtkTextureObject::Nearest);
    depth_->SetWrapS(vtkTextureObject::ClampToEdge);
    depth_->SetWrapT(vtkTextureObject::ClampToEdge);
    depth_->AllocateDepth(resolution_, resolution_, vtkTextureObject::Float32);
    colour_ = vtkSmartPointer<vtkTextureObject>::New();  // unused, but keeps the FBO complete everywhere
    colour_->SetContext(window);
    colour_->Allocate2D(resolution_, resolution_, 4, VTK_UNSIGNED_CHAR);
    fbo_ = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    fbo_->SetContext(window);
}

// Stage 1: the casters' depth, each map into its own tile of the texture, cleared to 1 (nothing
// cast) once for all of them. The viewport is the whole texture (the vertex shader places each map
// in its tile), the scissor box each tile's texels.
void ShadowMapPass::render_depth(const vtkRenderState* s, vtkOpenGLRenderWindow* window) {
    vtkOpenGLState* gl = window->GetState();
    vtkOpenGLState::ScopedglViewport viewport(gl);
    gl->vtkglViewport(0, 0, resolution_, resolution_);
    vtkOpenGLState::ScopedglScissor scissor_box(gl);
    vtkOpenGLState::ScopedglEnableDisable scissor(gl, GL_SCISSOR_TEST);
    gl->PushFramebufferBindings();
    fbo_->Bind();
    fbo_->AddColorAttachment(0, colour_);
    fbo_->AddDepthAttachment(depth_);
    fbo_->ActivateDrawBuffer(0);
    gl->vtkglDisable(GL_SCISSOR_TEST);  // the clear covers the whole texture
    gl->vtkglDepthMask(GL_TRUE);
    gl->vtkglClearDepth(1.0);
    gl->vtkglClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    gl->vtkglEnable(GL_SCISSOR_TEST);  // the viewport holds every tile: a map's casters stay in its own
    gl->vtkglEnable(GL_DEPTH_TEST);
    gl->vtkglDepthFunc(GL_LEQUAL);
    glEnable(GL_DEPTH_CLAMP);

    enter(Stage::depth);
    vtkRenderState depth_state(s->GetRenderer());
    depth_state.SetPropArrayAndCount(casters_.data(), static_cast<int>(casters_.size()));
    depth_state.SetFrameBuffer(fbo_);
    PreRender(&depth_state);
    for (int map = 0; map < static_cast<int>(setup_.maps.size()); ++map) render_map_depth(&depth_state, gl, map);
    PostRender(&depth_state);

    glDisable(GL_DEPTH_CLAMP);
    gl->PopFramebufferBindings();
}

// One map's casters into its tile: the props, or the map's own split casters. Every map draws with
// the same shader source, so nothing is rebuilt: the mappers call SetShaderParameters before each
// draw, which sends drawn_map_.
void ShadowMapPass::render_map_depth(const vtkRenderState* depth_state, vtkOpenGLState* gl, int map) {
    const Tile tile = tile_of(setup_.maps[map], resolution_);
    if (tile.width <= 0 || tile.height <= 0) return;  // a tile without texels: nothing to draw
    gl->vtkglScissor(tile.x, tile.y, tile.width, tile.height);
    drawn_map_ = map;
    const bool paraboloid = setup_.maps[map].projection == Projection::paraboloid;
    if (paraboloid) glEnable(GL_CLIP_DISTANCE0);  // behind the hemisphere: cut, as the CPU rasterizer does
    if (vtkProp* split = split_casters_[map]) {
        vtkRenderState split_state(depth_state->GetRenderer());
        split_state.SetPropArrayAndCount(&split, 1);
        split_state.SetFrameBuffer(depth_state->GetFrameBuffer());
        PreRender(&split_state);  // the pass's shader replacements, for this prop too
        depth_pass_->Render(&split_state);
        PostRender(&split_state);
    } else
        depth_pass_->Render(depth_state);
    if (paraboloid) glDisable(GL_CLIP_DISTANCE0);
}

// Stage 2: the scene, each fragment looked up in its map.
void ShadowMapPass::render_shaded(const vtkRenderState* s) {
    if (!shade_) return;
    int width = 0;  // where the renderer's image lies in the window: how pixel_rotation numbers its pixels
    s->GetRenderer()->GetTiledSizeAndOrigin(&width, &image_height_, &image_origin_.x, &image_origin_.y);
    enter(Stage::shade);
    depth_->Activate();
    PreRender(s);
    shade_->Render(s);
    NumberOfRenderedProps = shade_->GetNumberOfRenderedProps();
    PostRender(s);
    depth_->Deactivate();
}

bool ShadowMapPass::PreReplaceShaderValues(std::string& vertex, std::string&, std::string& fragment, vtkAbstractMapper*,
                                           vtkProp*) {
    const std::string projection = glsl_constants() + kProjectionDeclarations;
    if (stage_ == Stage::depth) {
        vtkShaderProgram::Substitute(vertex, "//VTK::PositionVC::Dec",
                                     "//VTK::PositionVC::Dec\n" + projection + kDepthDeclarations, false);
        return true;
    }
    pass_world_position(vertex);
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Dec",
                                 "//VTK::Light::Dec\n" + projection +
                                     stage2_switches(lookup_, output_, overlay_).declarations() + kLookupDeclarations +
                                     kBiasDeclarations + kFilterDeclarations + kOverlayDeclarations,
                                 false);
    declare_surface_shading(fragment);  // before the lookup's declarations, which use it
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Impl", kLookup, false);
    return true;
}

bool ShadowMapPass::PostReplaceShaderValues(std::string& vertex, std::string&, std::string&, vtkAbstractMapper*,
                                            vtkProp*) {
    // Our actors hold world coordinates (identity model matrix, no VBO shift): MC is world.
    if (stage_ == Stage::depth)
        vtkShaderProgram::Substitute(vertex, "gl_Position = MCDCMatrix * vertexMC;", kDepthPosition, true);
    return true;
}

bool ShadowMapPass::SetShaderParameters(vtkShaderProgram* shader_program, vtkAbstractMapper*, vtkProp*,
                                        vtkOpenGLVertexArrayObject*) {
    ProgramUniforms program(shader_program);
    MapArrays maps = map_arrays(setup_, resolution_);
    if (stage_ == Stage::depth)
        return all_set(set_projection_uniforms(program, maps), program.SetUniformi("shadowDrawnMap", drawn_map_),
                       program.SetUniform4f("shadowDrawnViewport", glm::value_ptr(maps.viewport[drawn_map_])));
    const bool unlit = output_ != Output::shaded;  // a grey level, white for lit: the lit mask or the visibility
    return all_set(set_projection_uniforms(program, maps), set_lookup_uniforms(program, maps, setup_),
                   program.SetUniformi("shadowDepth", depth_->GetTextureUnit()),
                   program.SetUniformi("shadowResolution", resolution_),
                   program.SetUniformi("shadowLitThreshold", output_ == Output::lit_mask),
                   set_filter_uniforms(program, lookup_, light_, taps_, image_origin_, image_height_),
                   set_surface_shading_uniforms(shader_program, frame_, unlit), set_overlay_uniforms(program, ramp_),
                   stage2_switches(lookup_, output_, overlay_).set(program));
}

void ShadowMapPass::ReleaseGraphicsResources(vtkWindow* w) {
    if (shade_) shade_->ReleaseGraphicsResources(w);
    depth_pass_->ReleaseGraphicsResources(w);
    for (vtkActor* split : split_casters_)
        if (split) split->ReleaseGraphicsResources(w);
    if (fbo_) fbo_->ReleaseGraphicsResources(w);
    if (depth_) depth_->ReleaseGraphicsResources(w);
    if (colour_) colour_->ReleaseGraphicsResources(w);
    fbo_ = nullptr;
    depth_ = colour_ = nullptr;
}

}  // namespace shadowlab
