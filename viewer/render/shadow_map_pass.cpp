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
#include "maps/map_lookup.hpp"
#include "maps/projection_kind.hpp"
#include "raster/paraboloid_edges.hpp"
#include "render/base_colour_texture.hpp"
#include "render/depth_texture.hpp"
#include "render/glsl_source.hpp"
#include "render/projection_glsl.hpp"
#include "render/program_uniforms.hpp"
#include "render/stage_one_casters.hpp"
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
    float log_near[kMaxMaps]{};
    float log_far[kMaxMaps]{};
    glm::vec3 face_axis[kMaxMaps]{};
    glm::vec4 viewport[kMaxMaps]{};
    glm::vec4 tile_texels[kMaxMaps]{};  // first and last texel (x, y, x, y) of the tile
};
// The arrays go to OpenGL as packed floats.
static_assert(sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(glm::vec4) == 4 * sizeof(float));
static_assert(sizeof(glm::mat4) == 16 * sizeof(float));

// The maps stage 1 draws: a reversed format's with their depth reversed (with_reversed_depth), so
// that the vertex shader computes s = 1 − d from each map's own terms, as the CPU rasterizer does.
ShadowSetup drawn_setup(const ShadowSetup& setup, const DepthFormat& format) {
    if (!format.reversed) return setup;
    ShadowSetup drawn = setup;
    for (ShadowMap& map : drawn.maps) map = with_reversed_depth(map);
    return drawn;
}

// The clip space's depth range: [0, w] (GL_ZERO_TO_ONE, OpenGL 4.5's glClipControl) or OpenGL's
// default [−w, w].
void zero_to_one_clip_depth(bool on) {
    if (!glClipControl)
        throw std::runtime_error("ShadowMapPass: a reversed depth format needs glClipControl (OpenGL 4.5)");
    glClipControl(GL_LOWER_LEFT, on ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
}

// The depth texture's internal format: the encoding's (GL_DEPTH_COMPONENT16, 24 or 32F).
int texture_format(DepthEncoding encoding) {
    switch (encoding) {
        case DepthEncoding::unorm16: return vtkTextureObject::Fixed16;
        case DepthEncoding::unorm24: return vtkTextureObject::Fixed24;
        case DepthEncoding::float32: return vtkTextureObject::Float32;
    }
    return vtkTextureObject::Float32;
}

MapArrays map_arrays(const std::vector<ShadowMap>& maps, int resolution) {
    MapArrays a;
    for (size_t i = 0; i < maps.size(); ++i) {
        const ShadowMap& map = maps[i];
        const Tile tile = tile_of(map, resolution);
        a.projection[i] = static_cast<int>(map.projection);
        a.world_to_uvz[i] = glm::mat4(map.world_to_uvz);
        a.paraboloid_centre[i] = glm::vec3(map.paraboloid.centre);
        a.paraboloid_frame[i] = glm::mat4(glm::mat3(map.paraboloid.frame_from_world));
        a.paraboloid_near[i] = static_cast<float>(map.paraboloid.near);
        a.paraboloid_far[i] = static_cast<float>(map.paraboloid.far);
        a.log_near[i] = static_cast<float>(map.log_warp.near);
        a.log_far[i] = static_cast<float>(map.log_warp.far);
        a.face_axis[i] = glm::vec3(map.face_axis);
        a.viewport[i] = glm::vec4(map.viewport);
        a.tile_texels[i] = glm::vec4(tile.x, tile.y, tile.x + tile.width - 1, tile.y + tile.height - 1);
    }
    return a;
}
MapArrays map_arrays(const ShadowSetup& setup, int resolution) { return map_arrays(setup.maps, resolution); }

// Rule::pages: each map's slot of the pool as page_table.glsl reads it, one texel per map in two
// rows: its viewport in the first, its tile's first and last texel (tile_of) in the second.
std::vector<glm::vec4> page_slots(const ShadowSetup& setup, int resolution) {
    const size_t count = setup.maps.size();
    std::vector<glm::vec4> slots(2 * count);
    for (size_t i = 0; i < count; ++i) {
        const Tile tile = tile_of(setup.maps[i], resolution);
        slots[i] = glm::vec4(setup.maps[i].viewport);
        slots[count + i] = glm::vec4(tile.x, tile.y, tile.x + tile.width - 1, tile.y + tile.height - 1);
    }
    return slots;
}

// Rule::pages: what SetSetup takes (the shaders compute each page's matrix as a linear map's, and
// hold kMaxPageLevels levels), or why not.
void check_pages(const ShadowSetup& setup) {
    const PageTable& t = setup.selection.pages;
    const size_t levels = t.levels.size(), per_level = size_t(t.pages_per_side) * size_t(t.pages_per_side);
    const auto fail = [](const std::string& why) { throw std::invalid_argument("ShadowMapPass: " + why); };
    if (levels > size_t(ShadowMapPass::kMaxPageLevels))
        fail("a page table of " + std::to_string(levels) + " levels; the GPU pass holds at most " +
             std::to_string(ShadowMapPass::kMaxPageLevels));
    if (t.resident.size() != levels * per_level || t.pages.size() != setup.maps.size())
        fail("a page table whose resident pages do not match its levels and the setup's maps");
    for (const ShadowMap& map : setup.maps)
        if (map.projection != Projection::linear) fail("a page that is not a linear map");
}

// Rule::pages: stage 2's per-map arrays as plain variables, which shadowSelectPage (page_table.glsl)
// fills with the selected page as map 0, and the selection by page: the general program's text with
// these lines exchanged, so that every other rule's programs stay as they are.
std::string paged(std::string text, const std::vector<std::pair<std::string, std::string>>& exchanges) {
    for (const auto& [from, to] : exchanges) {
        const size_t at = text.find(from);
        if (at == std::string::npos) throw std::logic_error("ShadowMapPass: no '" + from + "' in the lookup's GLSL");
        text.replace(at, from.size(), to);
    }
    return text;
}
// The filters' taps read through ShadowReader::tap_texel's page_across (shadowPageTapTexel,
// page_table.glsl, declared ahead of the filters that call it).
std::string paged_declarations(std::string text) {
    return paged(
        std::move(text),
        {{"uniform mat4 shadowMapWorldToUvz[shadowMaxMaps];", "mat4 shadowMapWorldToUvz[shadowMaxMaps];"},
         {"uniform vec4 shadowMapViewport[shadowMaxMaps];", "vec4 shadowMapViewport[shadowMaxMaps];"},
         {"uniform vec4 shadowMapTileTexels[shadowMaxMaps];",
          "vec4 shadowMapTileTexels[shadowMaxMaps];\nivec2 shadowPageTapTexel(vec2 uv, out vec2 centreUv);"},
         {"ivec2 texel = shadowTexelOf(i, m.uv + shadowRotated(shadowTaps[k].xy, c, s) * (radiusTexels / m.texels));",
          "vec2 centre;\n    ivec2 texel = shadowPageTapTexel(m.uv + shadowRotated(shadowTaps[k].xy, c, s) * "
          "(radiusTexels / m.texels), centre);"},
         {"float receiver = m.depth + dot(m.planeGradient, shadowTexelCentreUv(i, texel) - m.uv);",
          "float receiver = m.depth + dot(m.planeGradient, centre - m.uv);"},
         {"ivec2 texel = shadowTexelOf(i, m.uv + shadowRotated(shadowTaps[k].xy, c, s) * (search / m.texels));",
          "vec2 centre;\n    ivec2 texel = shadowPageTapTexel(m.uv + shadowRotated(shadowTaps[k].xy, c, s) * "
          "(search / m.texels), centre);"}});
}
std::string paged_lookup(std::string text) {
    return paged(std::move(text), {{"int i = shadowSelectMap(p);", "int i = shadowSelectPage(p);"}});
}
// The cascade overlay under pages: the selected page's level's colour (no page blends).
std::string paged_overlay(std::string text) {
    return paged(std::move(text),
                 {{"tint = w > 0.0 ? mix(shadowPalette[i], shadowPalette[i + 1], w) : shadowPalette[i];",
                   "tint = shadowPalette[shadowSelectedLevel % shadowMaxMaps];"}});
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
        program.SetUniform1fv("shadowMapParaboloidFar", kMaxMaps, maps.paraboloid_far),
        program.SetUniform1fv("shadowMapLogNear", kMaxMaps, maps.log_near),
        program.SetUniform1fv("shadowMapLogFar", kMaxMaps, maps.log_far));
}

// Stage 2: the rest of select_map, look_up and texel_of.
bool set_lookup_uniforms(ProgramUniforms& program, MapArrays& maps, const ShadowSetup& setup) {
    const MapSelection& s = setup.selection;
    const size_t splits = std::min(s.split_depths.size(), setup.maps.size() + 1);  // as by_view_depth reads them
    float split_depths[kMaxMaps + 1]{};
    std::transform(s.split_depths.begin(), s.split_depths.begin() + splits, split_depths,
                   [](double depth) { return static_cast<float>(depth); });
    return all_set(program.SetUniformi("shadowMapCount", static_cast<int>(setup.maps.size())),
                   program.SetUniform3fv("shadowMapFaceAxis", kMaxMaps, glm::value_ptr(maps.face_axis[0])),
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

// Stage 2 under Rule::pages: the levels, the table's size and the two textures' units.
bool set_page_uniforms(ProgramUniforms& program, const PageTable& table, int table_unit, int slots_unit) {
    glm::mat4 levels[ShadowMapPass::kMaxPageLevels]{};
    for (size_t k = 0; k < table.levels.size(); ++k) levels[k] = glm::mat4(table.levels[k].world_to_uvz);
    return all_set(program.SetUniformi("shadowPageLevelCount", static_cast<int>(table.levels.size())),
                   program.SetUniformMatrix4x4v("shadowPageLevelWorldToUvz", ShadowMapPass::kMaxPageLevels,
                                                glm::value_ptr(levels[0])),
                   program.SetUniformi("shadowPagesPerSide", table.pages_per_side),
                   program.SetUniformi("shadowPageTable", table_unit),
                   program.SetUniformi("shadowPageSlots", slots_unit));
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

// Whether the filter's taps turn per pixel (pcf's Poisson disk, pcss).
bool turns_taps(const ShadowFilter& f) {
    const FilterDescriptor& filter = filter_of(f);
    return filter.turns_taps && filter.turns_taps(f);
}

// A line of a dispatch by the filter whose index is shadowFilterKind: "if it is f, return <call>".
std::string filter_case(const FilterDescriptor& f, const std::string& call) {
    return "  if (shadowFilterKind == " + std::to_string(filter_index(f)) + ") return " + call + ";\n";
}

// Every filter's GLSL (a shipped filter's file, render/glsl/<name>_filter.glsl, or a registered
// one's own text), then, by the filter whose index is shadowFilterKind: map_visibility, one map's
// share of the light at the receiver (off the map, lit), and the moment encoding moment_map.glsl
// declares (the moments of a depth, what a texel stores of their blur).
std::string filters_glsl() {
    std::string functions, visibility, moments_of, stored;
    for (const FilterDescriptor& f : all_filters()) {
        functions += f.glsl.empty() ? std::string(glsl_source(f.name + "_filter")) : f.glsl;
        visibility += filter_case(f, "shadowFilter_" + f.name + "(i, m, rotation)");
        if (f.moments.of_depth) moments_of += filter_case(f, "shadowMomentsOf_" + f.name + "(depth)");
        if (f.moments.stored) stored += filter_case(f, "shadowStoredMoments_" + f.name + "(blurred)");
    }
    return functions +
           "float shadowMapVisibility(int i, vec3 position, vec3 normal, float rotation) {\n"
           "  ShadowMapReceiver m;\n"
           "  if (!shadowUnder(i, position, normal, m)) return 1.0;\n" +
           visibility + "  return 1.0;\n}\n" + "vec4 shadowMomentsOf(float depth) {\n" + moments_of +
           "  return vec4(0.0);\n}\n" + "vec4 shadowStoredMoments(vec4 blurred) {\n" + stored +
           "  return blurred;\n}\n";
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
    return all_set(
        program.SetUniformi("shadowTapCount", tap_count),
        program.SetUniform3fv("shadowTaps", ShadowMapPass::kMaxTaps, glm::value_ptr(taps[0])),
        program.SetUniformi("shadowTapsTurn", turns_taps(f)), real("shadowFilterRadiusTexels", f.radius_texels),
        real("shadowFilterRadiusWorld", f.radius_world), program.SetUniformi("shadowFilterKernelSize", f.kernel_size),
        real("shadowMinVariance", f.min_variance), real("shadowBleedReduction", f.bleed_reduction),
        real("shadowEvsmPositive", f.evsm_positive), real("shadowEvsmNegative", f.evsm_negative),
        real("shadowMsmMomentBias", f.msm_moment_bias), program.SetUniformi("shadowMsmQuantized", f.msm_quantized),
        real("shadowEsmExponent", f.esm_exponent), real("shadowBiasConstant", b.constant),
        real("shadowBiasSlopeScale", b.slope_scale), real("shadowBiasNormalOffset", b.normal_offset),
        program.SetUniformi("shadowLightDirectional", light.is_directional()),
        program.SetUniform3f("shadowLightPosition", glm::value_ptr(light.position)),
        real("shadowLightRadius", light.radius),
        real("shadowLightTanAngularRadius", std::tan(glm::radians(light.angular_radius_deg))),
        program.SetUniform2i("shadowImageOrigin", glm::value_ptr(image_origin)),
        program.SetUniformi("shadowImageHeight", image_height));
}

// The files of render/glsl named, one after the other.
template <class... Name>
std::string glsl(const Name&... names) {
    return (std::string(glsl_source(names)) + ...);
}

template <class Value>
std::string glsl_int_constant(const char* name, Value value) {
    return "const int " + std::string(name) + " = " + std::to_string(static_cast<int>(value)) + ";\n";
}

// The constants the shaders share with C++, written from it so that neither side can drift: the
// arrays' sizes, the values of MapSelection::Rule and MapOverlay, the
// overlay's strength and range, and PCSS's search limit.
std::string glsl_constants() {
    const auto constant = [](const char* name, auto value) { return glsl_int_constant(name, value); };
    const auto real = [](const char* name, double value) {
        return "const float " + std::string(name) + " = " + std::to_string(value) + ";\n";
    };
    using Rule = MapSelection::Rule;
    return constant("shadowMaxMaps", kMaxMaps) + constant("shadowMaxRampStops", ShadowMapPass::kMaxRampStops) +
           constant("shadowMaxMaskEdges", ShadowMapPass::kMaxMaskEdges) +
           constant("shadowMaxTaps", ShadowMapPass::kMaxTaps) +
           real("shadowMaxSearchTexels", ShadowReader::kMaxSearchTexels) + constant("shadowRuleOnly", Rule::only) +
           constant("shadowRuleViewDepth", Rule::view_depth) + constant("shadowRuleTileBounds", Rule::tile_bounds) +
           constant("shadowRuleFaceAxis", Rule::face_axis) + constant("shadowRuleHemisphere", Rule::hemisphere) +
           constant("shadowOverlayNone", MapOverlay::none) +
           constant("shadowOverlayCascadeIndex", MapOverlay::cascade_index) +
           real("shadowOverlayStrength", kOverlayStrength) + real("shadowTexelsLog2Range", kTexelsLog2Range);
}

// An alpha-tested actor's fragments tested (glsl/caster_alpha.glsl) before anything else; its texture
// coordinates passed on (declared before the test's declarations, which read them).
void replace_alpha_test(std::string& vertex, std::string& fragment) {
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Dec", "//VTK::Light::Dec\n" + glsl("caster_alpha"), false);
    vtkShaderProgram::Substitute(fragment, "//VTK::UniformFlow::Impl",
                                 "//VTK::UniformFlow::Impl\n  if (!shadowCasterKept()) discard;\n", false);
    pass_texture_coordinates(vertex, fragment);
}

bool set_alpha_test_uniforms(ProgramUniforms& program, const AlphaTest& alpha, int texture_unit) {
    return program.SetUniformi("shadowCasterAlpha", texture_unit) &&
           program.SetUniformf("shadowCasterAlphaFactor", static_cast<float>(alpha.factor)) &&
           program.SetUniformf("shadowCasterAlphaCutoff", static_cast<float>(alpha.cutoff));
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
constexpr int kDefaultFilter = 0;  // the first filter, the filter setting's default (hard)

struct Stage2Switches {
    int filter;  // the filter's index (filter_index), which shadowMapVisibility dispatches on
    bool receiver_plane;
    MapOverlay overlay;
    bool contact;  // contact shadows: always compiled in, so that off no program marches or reads their image

    bool compiled_in() const { return filter == kDefaultFilter && !receiver_plane && overlay == MapOverlay::none; }
    std::string declarations() const {
        const auto declared = [this](const char* name, int value) {
            return compiled_in() ? glsl_int_constant(name, value) : "uniform int " + std::string(name) + ";\n";
        };
        return declared("shadowFilterKind", filter) + declared("shadowBiasReceiverPlane", receiver_plane) +
               declared("shadowOverlay", static_cast<int>(overlay)) + glsl_int_constant("shadowContactOn", contact);
    }
    bool set(ProgramUniforms& program) const {
        return compiled_in() || all_set(program.SetUniformi("shadowFilterKind", filter),
                                        program.SetUniformi("shadowBiasReceiverPlane", receiver_plane),
                                        program.SetUniformi("shadowOverlay", static_cast<int>(overlay)));
    }
};

Stage2Switches stage2_switches(const ShadowLookup& lookup, ShadowMapPass::Output output, MapOverlay overlay) {
    return {.filter = filter_index(filter_of(lookup.filter)),
            .receiver_plane = lookup.bias.receiver_plane,
            .overlay = output == ShadowMapPass::Output::shaded ? overlay : MapOverlay::none,
            .contact = lookup.contact.on()};
}

}  // namespace

vtkStandardNewMacro(ShadowMapPass);

ShadowMapPass::ShadowMapPass() : depth_pass_(vtkSmartPointer<vtkOpaquePass>::New()) {}

ShadowMapPass::~ShadowMapPass() = default;

void ShadowMapPass::SetSetup(const ShadowSetup& setup, int resolution) {
    if (setup.selection.rule == MapSelection::Rule::pages)
        check_pages(setup);
    else if (setup.maps.size() > static_cast<size_t>(kMaxMaps))
        throw std::invalid_argument("ShadowMapPass: the setup has " + std::to_string(setup.maps.size()) +
                                    " maps; the GPU pass holds at most " + std::to_string(kMaxMaps));
    for (const ShadowMap& map : setup.maps)
        if (map.mask.size() > static_cast<size_t>(kMaxMaskEdges))
            throw std::invalid_argument("ShadowMapPass: a map's mask of " + std::to_string(map.mask.size()) +
                                        " half-planes; the GPU pass holds at most " + std::to_string(kMaxMaskEdges));
    setup_ = setup;
    resolution_ = resolution;
    page_textures_current_ = false;
    casters_per_map();
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
    casters_per_map();
    Modified();
}

// Once per setup, resolution and casters, not per frame: the split depends on nothing else. Alpha-tested
// casters are drawn as triangles into every map, whose texture coordinates the props lack.
void ShadowMapPass::casters_per_map() {
    map_casters_.assign(setup_.maps.size(), {});
    if (caster_triangles_.triangles.empty()) return;
    const std::vector<CasterActor> unsplit = caster_triangles_.alpha_tested()
                                                 ? caster_actors(caster_triangles_, casts_per_object_)
                                                 : std::vector<CasterActor>{};
    for (size_t i = 0; i < setup_.maps.size(); ++i)
        map_casters_[i] =
            splits_casters(setup_.maps[i])
                ? caster_actors(split_casters(caster_triangles_, casts_per_object_, setup_.maps[i], resolution_),
                                casts_per_object_)
                : unsplit;
}

// Each alpha test's texture, made once per context, for the casters drawn as triangles and the
// surfaces; those of tests no longer drawn let go.
void ShadowMapPass::prepare_alpha_textures(vtkOpenGLRenderWindow* window) {
    std::vector<std::shared_ptr<const AlphaTest>> drawn;
    for (const std::vector<CasterActor>& actors : map_casters_)
        for (const CasterActor& caster : actors) drawn.push_back(caster.alpha);
    for (const CasterActor& surface : alpha_surfaces_) drawn.push_back(surface.alpha);
    std::erase_if(alpha_textures_, [&](const auto& made) {
        return made.second->GetContext() != window || std::find(drawn.begin(), drawn.end(), made.first) == drawn.end();
    });
    for (const std::shared_ptr<const AlphaTest>& test : drawn)
        if (test && !alpha_texture(test.get())) alpha_textures_.emplace_back(test, alpha_texture_object(*test, window));
}

vtkTextureObject* ShadowMapPass::alpha_texture(const AlphaTest* test) const {
    const auto made = std::find_if(alpha_textures_.begin(), alpha_textures_.end(),
                                   [test](const auto& made) { return made.first.get() == test; });
    return made != alpha_textures_.end() ? made->second.GetPointer() : nullptr;
}

const AlphaTest* ShadowMapPass::alpha_of(vtkProp* prop) const {
    const auto holds = [prop](const CasterActor& caster) { return caster.actor.GetPointer() == prop; };
    for (const std::vector<CasterActor>& actors : map_casters_)
        if (auto found = std::find_if(actors.begin(), actors.end(), holds); found != actors.end())
            return found->alpha.get();
    const auto found = std::find_if(alpha_surfaces_.begin(), alpha_surfaces_.end(), holds);
    return found != alpha_surfaces_.end() ? found->alpha.get() : nullptr;
}

void ShadowMapPass::SetMaterialSurfaces(const std::vector<CasterActor>& surfaces) {
    alpha_surfaces_ = surfaces;
    base_colours_.set_surfaces(surfaces);
    Modified();
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
    if (paged()) prepare_page_textures(window);
    prepare_alpha_textures(window);
    base_colours_.prepare(window);
    render_depth(s, window);
    if (lookup_.contact.on())
        render_camera_depth(s, window);
    else if (contact_image_) {  // turned off: nothing kept
        contact_image_->release(window);
        contact_image_.reset();
    }
    render_shaded(s);
}

void ShadowMapPass::prepare_targets(vtkOpenGLRenderWindow* window) {
    if (depth_ && depth_->GetWidth() == static_cast<unsigned>(resolution_) && depth_->GetContext() == window &&
        allocated_encoding_ == lookup_.format.encoding)
        return;
    ReleaseGraphicsResources(window);
    depth_ = depth_texture(window, resolution_, resolution_, texture_format(lookup_.format.encoding));
    allocated_encoding_ = lookup_.format.encoding;
    colour_ = completing_colour_texture(window, resolution_, resolution_);
    fbo_ = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    fbo_->SetContext(window);
}

// Rule::pages: the page table and the slots as textures, read by texelFetch alone (nearest, no mipmaps).
void ShadowMapPass::prepare_page_textures(vtkOpenGLRenderWindow* window) {
    if (page_textures_current_ && page_table_ && page_table_->GetContext() == window) return;
    const auto texture = [window](unsigned internal_format, unsigned format, unsigned type) {
        auto t = vtkSmartPointer<vtkTextureObject>::New();
        t->SetContext(window);
        t->SetInternalFormat(internal_format);
        t->SetFormat(format);
        t->SetDataType(type);
        t->SetMinificationFilter(vtkTextureObject::Nearest);
        t->SetMagnificationFilter(vtkTextureObject::Nearest);
        t->SetWrapS(vtkTextureObject::ClampToEdge);
        t->SetWrapT(vtkTextureObject::ClampToEdge);
        return t;
    };
    const PageTable& table = setup_.selection.pages;
    std::vector<int> resident = table.resident;
    const auto side = static_cast<unsigned>(table.pages_per_side);
    const auto rows = static_cast<unsigned>(table.levels.size()) * side;
    if (rows == 0) resident = {-1};  // a table without levels: one texel, no page
    GLint max_side = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
    if (rows > static_cast<unsigned>(max_side) || setup_.maps.size() > static_cast<size_t>(max_side))
        throw std::invalid_argument("ShadowMapPass: a page table of " + std::to_string(rows) + " rows and " +
                                    std::to_string(setup_.maps.size()) + " pages; this OpenGL's textures hold " +
                                    std::to_string(max_side) + " texels per side");
    page_table_ = texture(GL_R32I, GL_RED_INTEGER, GL_INT);
    if (!page_table_->Create2DFromRaw(std::max(side, 1u), std::max(rows, 1u), 1, VTK_INT, resident.data()))
        throw std::runtime_error("ShadowMapPass: the page table's texture could not be made");
    std::vector<glm::vec4> slots = page_slots(setup_, resolution_);
    if (slots.empty()) slots.assign(2, glm::vec4(0.0f));  // no page: nothing read
    page_slots_ = texture(GL_RGBA32F, GL_RGBA, GL_FLOAT);
    if (!page_slots_->Create2DFromRaw(static_cast<unsigned>(slots.size() / 2), 2, 4, VTK_FLOAT, slots.data()))
        throw std::runtime_error("ShadowMapPass: the page slots' texture could not be made");
    page_textures_current_ = true;
}

// Stage 1: the casters' depth, each map into its own tile of the texture, cleared to the far value
// (nothing cast) once for all of them. The viewport is the whole texture (the vertex shader places
// each map in its tile), the scissor box each tile's texels. A reversed format stores s = 1 − d: the
// clip space's depth runs over [0, w] (glClipControl), so that window depth is s itself, not
// (2 s − w) / w + 1 halved, which would cancel where s is small; cleared to 0, the greater s nearer.
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
    const bool reversed = lookup_.format.reversed;
    if (reversed) zero_to_one_clip_depth(true);
    gl->vtkglDisable(GL_SCISSOR_TEST);  // the clear covers the whole texture
    gl->vtkglDepthMask(GL_TRUE);
    gl->vtkglClearDepth(reversed ? 0.0 : 1.0);
    gl->vtkglClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    gl->vtkglEnable(GL_SCISSOR_TEST);  // the viewport holds every tile: a map's casters stay in its own
    gl->vtkglEnable(GL_DEPTH_TEST);
    gl->vtkglDepthFunc(reversed ? GL_GEQUAL : GL_LEQUAL);
    glEnable(GL_DEPTH_CLAMP);

    enter(Stage::depth);
    vtkRenderState depth_state(s->GetRenderer());
    depth_state.SetPropArrayAndCount(casters_.data(), static_cast<int>(casters_.size()));
    depth_state.SetFrameBuffer(fbo_);
    PreRender(&depth_state);
    for (int map = 0; map < static_cast<int>(setup_.maps.size()); ++map) render_map_depth(&depth_state, gl, map);
    PostRender(&depth_state);

    glDisable(GL_DEPTH_CLAMP);
    if (reversed) {  // OpenGL's defaults again, which VTK's passes draw with
        zero_to_one_clip_depth(false);
        gl->vtkglDepthFunc(GL_LEQUAL);
        gl->vtkglClearDepth(1.0);
    }
    gl->PopFramebufferBindings();
}

// One map's casters into its tile: the props, or the map's own casters as triangles (split, or alpha-
// tested: each test's with its texture bound). Every map draws with the same shader source, so nothing
// is rebuilt: the mappers call SetShaderParameters before each draw, which sends drawn_map_.
void ShadowMapPass::render_map_depth(const vtkRenderState* depth_state, vtkOpenGLState* gl, int map) {
    const Tile tile = tile_of(setup_.maps[map], resolution_);
    if (tile.width <= 0 || tile.height <= 0) return;  // a tile without texels: nothing to draw
    gl->vtkglScissor(tile.x, tile.y, tile.width, tile.height);
    drawn_map_ = map;
    const bool clips = projection_kind(setup_.maps[map]).clip_distance != nullptr;
    if (clips) glEnable(GL_CLIP_DISTANCE0);  // behind its plane (a hemisphere's): cut, as the CPU rasterizer does
    const int mask_edges = static_cast<int>(setup_.maps[map].mask.size());
    for (int k = 0; k < mask_edges; ++k) glEnable(GL_CLIP_DISTANCE1 + k);  // outside its mask: cut likewise
    for (const CasterActor& caster : map_casters_[map]) {
        vtkProp* prop = caster.actor;
        vtkRenderState caster_state(depth_state->GetRenderer());
        caster_state.SetPropArrayAndCount(&prop, 1);
        caster_state.SetFrameBuffer(depth_state->GetFrameBuffer());
        vtkTextureObject* alpha = caster.alpha ? alpha_texture(caster.alpha.get()) : nullptr;
        if (alpha) alpha->Activate();
        PreRender(&caster_state);  // the pass's shader replacements, for this prop too
        depth_pass_->Render(&caster_state);
        PostRender(&caster_state);
        if (alpha) alpha->Deactivate();
    }
    if (map_casters_[map].empty()) depth_pass_->Render(depth_state);
    if (clips) glDisable(GL_CLIP_DISTANCE0);
    for (int k = 0; k < mask_edges; ++k) glDisable(GL_CLIP_DISTANCE1 + k);
}

// Contact shadows: the renderer's opaque props from its camera, VTK's shaders unchanged but for the
// alpha-tested surfaces' test (as stage 2 discards them, and the CPU's rays pass their holes), into
// the camera's depth image that stage 2 marches in.
void ShadowMapPass::render_camera_depth(const vtkRenderState* s, vtkOpenGLRenderWindow* window) {
    if (!contact_image_) contact_image_.emplace();
    contact_image_->prepare(s->GetRenderer(), window);
    vtkOpenGLState* gl = window->GetState();
    contact_image_->begin_drawing(gl);
    enter(Stage::camera_depth);
    vtkRenderState camera_state(s->GetRenderer());
    camera_state.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
    camera_state.SetFrameBuffer(contact_image_->framebuffer());
    for (auto& [test, texture] : alpha_textures_) texture->Activate();
    PreRender(&camera_state);
    depth_pass_->Render(&camera_state);
    PostRender(&camera_state);
    for (auto& [test, texture] : alpha_textures_) texture->Deactivate();
    contact_image_->end_drawing(gl);
}

// Stage 2: the scene, each fragment looked up in its map.
void ShadowMapPass::render_shaded(const vtkRenderState* s) {
    if (!shade_) return;
    int width = 0;  // where the renderer's image lies in the window: how pixel_rotation numbers its pixels
    s->GetRenderer()->GetTiledSizeAndOrigin(&width, &image_height_, &image_origin_.x, &image_origin_.y);
    enter(Stage::shade);
    depth_->Activate();
    for (auto& [test, texture] : alpha_textures_) texture->Activate();  // each on a unit of its own
    if (paged()) {
        page_table_->Activate();
        page_slots_->Activate();
    }
    if (contact_image_) contact_image_->activate();
    PreRender(s);
    shade_->Render(s);
    NumberOfRenderedProps = shade_->GetNumberOfRenderedProps();
    PostRender(s);
    base_colours_.unbind();
    if (contact_image_) contact_image_->deactivate();
    if (paged()) {
        page_slots_->Deactivate();
        page_table_->Deactivate();
    }
    for (auto& [test, texture] : alpha_textures_) texture->Deactivate();
    depth_->Deactivate();
}

bool ShadowMapPass::PreReplaceShaderValues(std::string& vertex, std::string&, std::string& fragment, vtkAbstractMapper*,
                                           vtkProp* prop) {
    if (stage_ == Stage::camera_depth) {  // VTK's own depth, as stage 2 rasterizes it: holes and all
        if (alpha_of(prop)) replace_alpha_test(vertex, fragment);
        return true;
    }
    const std::string projection = glsl_constants() + glsl("map_projection") + projection_glsl();
    if (stage_ == Stage::depth) {
        vtkShaderProgram::Substitute(vertex, "//VTK::PositionVC::Dec",
                                     "//VTK::PositionVC::Dec\n" + projection + glsl("caster_depth"), false);
        if (alpha_of(prop)) replace_alpha_test(vertex, fragment);
        return true;
    }
    pass_world_position(vertex);
    std::string declarations = projection + stage2_switches(lookup_, output_, overlay_).declarations() +
                               glsl("map_lookup", "depth_bias", "hash", "kernel_taps", "shadow_reader", "chebyshev",
                                    "moment_map", "contact_shadow") +
                               filters_glsl();
    std::string overlay = glsl("map_overlay");
    std::string lookup = glsl("shadow_lookup");
    if (paged()) {  // a program of its own: the per-map arrays filled by the page selection
        declarations = paged_declarations(std::move(declarations)) +
                       glsl_int_constant("shadowMaxPageLevels", kMaxPageLevels) + glsl("page_table");
        overlay = paged_overlay(std::move(overlay));
        lookup = paged_lookup(std::move(lookup));
    }
    declarations += overlay;
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Dec", "//VTK::Light::Dec\n" + declarations, false);
    declare_surface_shading(fragment);  // before the lookup's declarations, which use it
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Impl", lookup, false);
    // Declared last, so that their declarations come first: the texture coordinates, then what reads them.
    const bool textured = base_colours_.textured(prop) != nullptr;
    if (textured) BaseColourTextures::replace_colour(fragment);
    if (alpha_of(prop))
        replace_alpha_test(vertex, fragment);
    else if (textured)
        pass_texture_coordinates(vertex, fragment);
    return true;
}

bool ShadowMapPass::PostReplaceShaderValues(std::string& vertex, std::string&, std::string&, vtkAbstractMapper*,
                                            vtkProp*) {
    // Our actors hold world coordinates (identity model matrix, no VBO shift): MC is world.
    if (stage_ == Stage::depth)
        vtkShaderProgram::Substitute(vertex, "gl_Position = MCDCMatrix * vertexMC;", glsl("caster_position"), true);
    return true;
}

bool ShadowMapPass::SetShaderParameters(vtkShaderProgram* shader_program, vtkAbstractMapper*, vtkProp* prop,
                                        vtkOpenGLVertexArrayObject*) {
    ProgramUniforms program(shader_program);
    if (stage_ == Stage::camera_depth) {
        const AlphaTest* alpha = alpha_of(prop);
        return !alpha || set_alpha_test_uniforms(program, *alpha, alpha_texture(alpha)->GetTextureUnit());
    }
    const DepthFormat& format = lookup_.format;
    if (stage_ == Stage::depth) {
        if (const AlphaTest* alpha = alpha_of(prop))
            if (!set_alpha_test_uniforms(program, *alpha, alpha_texture(alpha)->GetTextureUnit())) return false;
        // Pages: the drawn page alone, as map 0 (a setup of pages outgrows the arrays).
        const int drawn_map = paged() ? 0 : drawn_map_;
        MapArrays drawn =
            paged()
                ? map_arrays({format.reversed ? with_reversed_depth(setup_.maps[drawn_map_]) : setup_.maps[drawn_map_]},
                             resolution_)
                : map_arrays(drawn_setup(setup_, format), resolution_);
        glm::vec3 mask[kMaxMaskEdges]{};
        const std::vector<glm::dvec3>& drawn_mask = setup_.maps[drawn_map_].mask;
        std::transform(drawn_mask.begin(), drawn_mask.end(), mask, [](const glm::dvec3& h) { return glm::vec3(h); });
        return all_set(set_projection_uniforms(program, drawn), program.SetUniformi("shadowDrawnMap", drawn_map),
                       program.SetUniform3fv("shadowDrawnMask", kMaxMaskEdges, glm::value_ptr(mask[0])),
                       program.SetUniform4f("shadowDrawnViewport", glm::value_ptr(drawn.viewport[drawn_map])),
                       program.SetUniformi("shadowDepthZeroToOne", format.reversed));
    }
    if (const AlphaTest* alpha = alpha_of(prop))
        if (!set_alpha_test_uniforms(program, *alpha, alpha_texture(alpha)->GetTextureUnit())) return false;
    if (!base_colours_.bind(prop, shader_program)) return false;
    // Pages: the arrays the page selection fills are no uniforms; the others stay zero (linear maps).
    MapArrays maps = paged() ? MapArrays{} : map_arrays(setup_, resolution_);
    const bool unlit = output_ != Output::shaded;  // a grey level, white for lit: the lit mask or the visibility
    return all_set(set_projection_uniforms(program, maps), set_lookup_uniforms(program, maps, setup_),
                   program.SetUniformi("shadowDepth", depth_->GetTextureUnit()),
                   program.SetUniformi("shadowResolution", resolution_),
                   program.SetUniformi("shadowDepthReversed", format.reversed),
                   program.SetUniformi("shadowLitThreshold", output_ == Output::lit_mask),
                   set_filter_uniforms(program, lookup_, light_, taps_, image_origin_, image_height_),
                   set_surface_shading_uniforms(shader_program, frame_, unlit), set_overlay_uniforms(program, ramp_),
                   stage2_switches(lookup_, output_, overlay_).set(program),
                   !paged() || set_page_uniforms(program, setup_.selection.pages, page_table_->GetTextureUnit(),
                                                 page_slots_->GetTextureUnit()),
                   !contact_image_ || contact_image_->set_uniforms(program, lookup_.contact));
}

void ShadowMapPass::ReleaseGraphicsResources(vtkWindow* w) {
    if (shade_) shade_->ReleaseGraphicsResources(w);
    depth_pass_->ReleaseGraphicsResources(w);
    for (const std::vector<CasterActor>& actors : map_casters_)
        for (const CasterActor& caster : actors) caster.actor->ReleaseGraphicsResources(w);
    for (auto& [test, texture] : alpha_textures_) texture->ReleaseGraphicsResources(w);
    alpha_textures_.clear();
    base_colours_.release(w);
    if (fbo_) fbo_->ReleaseGraphicsResources(w);
    if (depth_) depth_->ReleaseGraphicsResources(w);
    if (colour_) colour_->ReleaseGraphicsResources(w);
    if (page_table_) page_table_->ReleaseGraphicsResources(w);
    if (page_slots_) page_slots_->ReleaseGraphicsResources(w);
    if (contact_image_) contact_image_->release(w);
    contact_image_.reset();
    fbo_ = nullptr;
    depth_ = colour_ = page_table_ = page_slots_ = nullptr;
    page_textures_current_ = false;
}

}  // namespace shadowlab
