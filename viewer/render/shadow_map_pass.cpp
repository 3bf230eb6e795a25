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

#include "raster/paraboloid_edges.hpp"
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
    float z_bias_scale[kMaxMaps]{};
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
        a.z_bias_scale[i] = static_cast<float>(map.z_bias_scale);
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
bool set_projection_uniforms(vtkShaderProgram* program, MapArrays& maps) {
    return all_set(
        program->SetUniform1iv("shadowMapProjection", kMaxMaps, maps.projection),
        program->SetUniformMatrix4x4v("shadowMapWorldToUvz", kMaxMaps, glm::value_ptr(maps.world_to_uvz[0])),
        program->SetUniform3fv("shadowMapParaboloidCentre", kMaxMaps, glm::value_ptr(maps.paraboloid_centre[0])),
        program->SetUniformMatrix4x4v("shadowMapParaboloidFrame", kMaxMaps, glm::value_ptr(maps.paraboloid_frame[0])),
        program->SetUniform1fv("shadowMapParaboloidNear", kMaxMaps, maps.paraboloid_near),
        program->SetUniform1fv("shadowMapParaboloidFar", kMaxMaps, maps.paraboloid_far));
}

// Stage 2: the rest of select_map, look_up and texel_of.
bool set_lookup_uniforms(vtkShaderProgram* program, MapArrays& maps, const ShadowSetup& setup) {
    const MapSelection& s = setup.selection;
    const size_t splits = std::min(s.split_depths.size(), setup.maps.size() + 1);  // as by_view_depth reads them
    float split_depths[kMaxMaps + 1]{};
    std::transform(s.split_depths.begin(), s.split_depths.begin() + splits, split_depths,
                   [](double depth) { return static_cast<float>(depth); });
    return all_set(program->SetUniformi("shadowMapCount", static_cast<int>(setup.maps.size())),
                   program->SetUniform1iv("shadowMapCubeFace", kMaxMaps, maps.cube_face),
                   program->SetUniform4fv("shadowMapViewport", kMaxMaps, glm::value_ptr(maps.viewport[0])),
                   program->SetUniform4fv("shadowMapTileTexels", kMaxMaps, glm::value_ptr(maps.tile_texels[0])),
                   program->SetUniform1fv("shadowMapZBiasScale", kMaxMaps, maps.z_bias_scale),
                   program->SetUniformi("shadowSelectionRule", static_cast<int>(s.rule)),
                   program->SetUniform3f("shadowSelectionEye", glm::value_ptr(s.eye)),
                   program->SetUniform3f("shadowSelectionViewAxis", glm::value_ptr(s.view_axis)),
                   program->SetUniform1fv("shadowSelectionSplitDepths", kMaxMaps + 1, split_depths),
                   program->SetUniformi("shadowSelectionSplitCount", static_cast<int>(splits)),
                   program->SetUniformf("shadowSelectionBlendBand", static_cast<float>(s.blend_band)),
                   program->SetUniform3f("shadowSelectionCentre", glm::value_ptr(s.centre)));
}

// Stage 2: the overlay, its map palette and its ramp (render/map_overlay.hpp).
bool set_overlay_uniforms(vtkShaderProgram* program, MapOverlay overlay, const std::vector<glm::vec3>& ramp) {
    static_assert(kMapPalette.size() == kMaxMaps, "one palette colour per map the pass holds");
    std::vector<glm::vec3> stops = ramp;
    stops.resize(ShadowMapPass::kMaxRampStops);
    return all_set(program->SetUniformi("shadowOverlay", static_cast<int>(overlay)),
                   program->SetUniform3fv("shadowPalette", kMaxMaps, glm::value_ptr(kMapPalette[0])),
                   program->SetUniform3fv("shadowRamp", ShadowMapPass::kMaxRampStops, glm::value_ptr(stops[0])),
                   program->SetUniformi("shadowRampCount", static_cast<int>(ramp.size())));
}

// The constants the shaders share with C++, written from it so that neither side can drift: the
// arrays' sizes, the values of Projection, MapSelection::Rule and MapOverlay, and the overlay's
// strength and range.
std::string glsl_constants() {
    const auto constant = [](const char* name, auto value) {
        return "const int " + std::string(name) + " = " + std::to_string(static_cast<int>(value)) + ";\n";
    };
    const auto real = [](const char* name, double value) {
        return "const float " + std::string(name) + " = " + std::to_string(value) + ";\n";
    };
    using Rule = MapSelection::Rule;
    return constant("shadowMaxMaps", kMaxMaps) + constant("shadowMaxRampStops", ShadowMapPass::kMaxRampStops) +
           constant("shadowParaboloid", Projection::paraboloid) + constant("shadowRuleOnly", Rule::only) +
           constant("shadowRuleViewDepth", Rule::view_depth) + constant("shadowRuleTileBounds", Rule::tile_bounds) +
           constant("shadowRuleCubeFace", Rule::cube_face) + constant("shadowRuleHemisphere", Rule::hemisphere) +
           constant("shadowOverlayNone", MapOverlay::none) +
           constant("shadowOverlayCascadeIndex", MapOverlay::cascade_index) +
           real("shadowOverlayStrength", kOverlayStrength) + real("shadowTexelsLog2Range", kTexelsLog2Range);
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

// Stage 2, after the projections: select_map, look_up and texel_of (maps/map_lookup.cpp) line by
// line. The slope-scaled bias is the CPU's (metrics/shadow_error.cpp, slope_scaled_bias) under the
// selected map: the texel's world size across the light, 1 / (N σ_min(J)) with N the tile's texels
// per side and J = d(u, v) per world unit across the light, times 1 + tan θ (clamped to 10), θ
// between the seen side's normal and the light.
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
uniform float shadowBias;  // world units along the light; < 0: slope-scaled per fragment
uniform int shadowResolution;
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
float shadowSlopeScaledBias(int i, vec3 p, vec3 n) {
  vec3 l = surfaceAlongLight(p);
  vec3 a = normalize(cross(l, abs(l.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  vec3 b = cross(l, a);
  vec2 ja = shadowUvDerivative(i, p, a), jb = shadowUvDerivative(i, p, b);
  float t = dot(ja, ja) + dot(jb, jb), d = ja.x * jb.y - ja.y * jb.x;
  float smallest = 0.5 * (t - sqrt(max(t * t - 4.0 * d * d, 0.0)));  // σ_min²
  float texels = (shadowMapViewport[i].z - shadowMapViewport[i].x) * float(shadowResolution);  // tile_resolution
  float texel = 1.0 / (texels * sqrt(max(smallest, 1e-30)));
  float c = dot(n, -l);
  float tanTheta = min(10.0, sqrt(max(0.0, 1.0 - c * c)) / max(c, 1e-6));
  return texel * (1.0 + tanTheta);
}
// One map's verdict at p (shadow_amount's): 1 shadowed, 0 lit; off the map or behind its centre, lit.
float shadowOf(int i, vec3 p, vec3 n) {
  vec4 h = shadowHomogeneous(i, p);
  if (!shadowOnMap(h)) return 0.0;
  float bias = shadowBias >= 0.0 ? shadowBias : shadowSlopeScaledBias(i, p, n);
  float depth = (h.z - shadowMapZBiasScale[i] * bias) / h.w;
  return depth > texelFetch(shadowDepth, shadowTexelOf(i, h.xy / h.w), 0).r ? 1.0 : 0.0;
}
)";

// Stage 2, the overlay: the selected map's palette colour (in a band both, crossfaded by the
// weight), or its texels per pixel on the ramp: the pixel's footprint in the map's texels as OpenGL
// sizes it to pick a mip level (the scale factor ρ, §8.14 of the 4.5 core profile): the longer of
// d(u, v)/dx and d(u, v)/dy across the screen, in the tile's texels.
constexpr const char* kOverlayDeclarations = R"(
uniform int shadowOverlay;
uniform vec3 shadowPalette[shadowMaxMaps];
uniform vec3 shadowRamp[shadowMaxRampStops];
uniform int shadowRampCount;
vec3 shadowRampColour(float t) {
  float s = clamp(t, 0.0, 1.0) * float(shadowRampCount - 1);
  int k = min(int(s), shadowRampCount - 2);
  return mix(shadowRamp[k], shadowRamp[k + 1], s - float(k));
}
float shadowTexelsPerPixel(int i, vec3 p, vec3 dpdx, vec3 dpdy) {
  float texels = (shadowMapViewport[i].z - shadowMapViewport[i].x) * float(shadowResolution);  // tile_resolution
  return texels * max(length(shadowUvDerivative(i, p, dpdx)), length(shadowUvDerivative(i, p, dpdy)));
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

// The lookup, after VTK's lighting: shadow_amount, the selected map's verdict crossfaded with the
// next map's inside a blend band; no map counts as lit. The shading is linear in `lit`, so that
// shading with 1 - amount mixes the two maps' shadings by the weight; the lit mask thresholds the
// amount at one half, as in_shadow does. The seen normal and the position's screen derivatives are
// only defined in uniform control flow: taken before the lookup branches. The colour is the shared
// surface shading's, with the overlay over it.
constexpr const char* kLookup = R"(//VTK::Light::Impl
  {
    vec3 p = surfaceWorldVSOutput.xyz;
    vec3 n = surfaceSeenNormal(p);
    vec3 dpdx = dFdx(p), dpdy = dFdy(p);
    int i = shadowSelectMap(p);
    float w = shadowBlendWeight(i, p);
    float amount = 0.0;
    if (i >= 0) amount = w > 0.0 ? mix(shadowOf(i, p, n), shadowOf(i + 1, p, n), w) : shadowOf(i, p, n);
    float lit = surfaceLitMask == 1 ? (amount >= 0.5 ? 0.0 : 1.0) : 1.0 - amount;
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

void ShadowMapPass::SetBias(double bias, const glm::dvec4& light, const glm::dvec3& eye) {
    bias_ = static_cast<float>(bias);
    frame_ = {.light = glm::vec4(light), .eye = glm::vec3(eye)};
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
    enter(Stage::shade);
    depth_->Activate();
    PreRender(s);
    shade_->Render(s);
    NumberOfRenderedProps = shade_->GetNumberOfRenderedProps();
    PostRender(s);
    depth_->Deactivate();
}

bool ShadowMapPass::PreReplaceShaderValues(std::string& vertex, std::string&, std::string& fragment,
                                           vtkAbstractMapper*, vtkProp*) {
    const std::string projection = glsl_constants() + kProjectionDeclarations;
    if (stage_ == Stage::depth) {
        vtkShaderProgram::Substitute(vertex, "//VTK::PositionVC::Dec",
                                     "//VTK::PositionVC::Dec\n" + projection + kDepthDeclarations, false);
        return true;
    }
    pass_world_position(vertex);
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Dec",
                                 "//VTK::Light::Dec\n" + projection + kLookupDeclarations + kOverlayDeclarations, false);
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

bool ShadowMapPass::SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*,
                                        vtkOpenGLVertexArrayObject*) {
    MapArrays maps = map_arrays(setup_, resolution_);
    if (stage_ == Stage::depth)
        return all_set(set_projection_uniforms(program, maps), program->SetUniformi("shadowDrawnMap", drawn_map_),
                       program->SetUniform4f("shadowDrawnViewport", glm::value_ptr(maps.viewport[drawn_map_])));
    return all_set(set_projection_uniforms(program, maps), set_lookup_uniforms(program, maps, setup_),
                   program->SetUniformi("shadowDepth", depth_->GetTextureUnit()),
                   program->SetUniformf("shadowBias", bias_), program->SetUniformi("shadowResolution", resolution_),
                   set_surface_shading_uniforms(program, frame_, output_ == Output::lit_mask),
                   set_overlay_uniforms(program, output_ == Output::lit_mask ? MapOverlay::none : overlay_, ramp_));
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
