#pragma once
// Shadow mapping with a method's own maps: up to kMaxMaps of them, each linear (any world_to_uvz,
// perspective warps included), a paraboloid hemisphere or a cube face, or any number of a virtual
// map's pages (MapSelection::Rule::pages), each in its tile of one depth texture. Our own render
// pass, because vtkShadowMapPass fixes its own light camera.
//
// Stage 1 renders the casters' depth into an FBO depth texture of the lookup's depth format
// (GL_DEPTH_COMPONENT16, 24 or 32F; reversed: s = 1 − d from each map's reversed depth, with
// glClipControl's [0, w] depth range, cleared to 0 and kept where greater), once per map into that
// map's tile (placed by the vertex shader exactly where the CPU rasterizer places it, however its
// edges fall between texels, and scissored to the tile's texels; depth clamped, as the CPU rasterizer
// clamps casters before the near plane; a map with a mask clipped to it by clip distances, as the CPU
// rasterizer clips it (maps/map_mask.hpp); a paraboloid clipped to its hemisphere, and its casters split first
// where the map asks, as the CPU rasterizer splits them: SetCasterTriangles; a page as any map, by its
// own matrix). Stage 2 renders the scene
// through `shade` (normally a vtkRenderStepsPass) and reads each fragment's visibility as the one CPU
// lookup does (lookup/shadow_reader.cpp), step by step: the setup's rule picks the map (under
// Rule::pages, the finest resident page from the page table and the pool's slots, two textures, its
// matrix from its level's: render/glsl/page_table.glsl); the normal
// offset moves the point; the depth bias (world lengths) moves it toward the light for its depth
// alone, read exactly after the division by w whatever the map's perspective; then the filter: hard,
// pcf, pcss (blocker search, penumbra, PCF) over the CPU's own tap lists, or vsm/evsm on the
// box-blurred moments, which the fragment shader sums from the depth texture itself. Inside a blend
// band (blend_of) the two maps' visibilities are crossfaded. With the lookup's contact shadows on, a
// pass before stage 2 draws the camera's depth image (render/contact_depth_image.hpp) and the
// visibility is multiplied by the march through it, as receiver_visibility multiplies. The shading mixes by 1 −
// visibility (soft shadows shade by themselves), the lit mask thresholds the visibility at one half, as the CPU's
// verdicts do. An overlay (render/map_overlay.hpp) may tint the result.
#include <memory>
#include <optional>
#include <utility>
#include <vector>
#include <glm/glm.hpp>
#include <vtkOpenGLRenderPass.h>
#include <vtkSmartPointer.h>

#include "lookup/lookup_settings.hpp"
#include "maps/shadow_map.hpp"
#include "render/contact_depth_image.hpp"
#include "render/map_overlay.hpp"
#include "render/base_colour_texture.hpp"
#include "render/stage_one_casters.hpp"
#include "render/surface_shading.hpp"
#include "scene/light.hpp"
#include "scene/tessellation.hpp"

class vtkActor;
class vtkOpaquePass;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkProp;
class vtkTextureObject;

namespace shadowlab {

class ShadowMapPass : public vtkOpenGLRenderPass {
public:
    static ShadowMapPass* New();
    vtkTypeMacro(ShadowMapPass, vtkOpenGLRenderPass);

    static constexpr int kMaxMaps = 8;         // the shaders' uniform arrays hold this many maps (pages aside)
    static constexpr int kMaxPageLevels = 24;  // and this many levels of a virtual map's page table
    static constexpr int kMaxTaps = 81;        // and this many filter taps: kernel_size <= 9
    static constexpr int kMaxMaskEdges = 4;    // and this many half-planes of a map's mask (clip distances 1..4)

    // What stage 2 writes: the surface shading (render/surface_shading.hpp), shadow tinted; white
    // where lit and black where shadowed; or the visibility itself as a grey level, unlit (for tests).
    enum class Output { shaded, lit_mask, visibility };

    // The maps, their tiles and the rule that picks one per point; resolution: texels per side of
    // the whole texture. Throws std::invalid_argument for more than kMaxMaps maps, unless the rule is
    // pages: then any number of linear maps, its table of at most kMaxPageLevels levels; and for a
    // map's mask of more than kMaxMaskEdges half-planes.
    void SetSetup(const ShadowSetup& setup, int resolution);
    // How fragments read the maps (the filter and the bias, as ShadowReader reads them) and how stage 1
    // stores them (lookup.format, as rasterize_depth stores them); the light and
    // the eye's position in the setup's coordinates (PCSS sizes its search and penumbra by the light).
    // Throws std::invalid_argument for a filter of more than kMaxTaps taps.
    void SetLookup(const ShadowLookup& lookup, const Light& light, const glm::dvec3& eye);
    void SetCasters(const std::vector<vtkProp*>& casters);  // the props drawn into the maps
    // The same casters as triangles, in the setup's coordinates, with their objects' flags: a map that
    // splits its casters (a paraboloid with max_sagitta_texels > 0, raster/paraboloid_edges.hpp) draws
    // them split exactly as the CPU rasterizer splits them, instead of the props. Until they are given,
    // every map draws the props.
    void SetCasterTriangles(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object);
    // Stage 2's surfaces with a material (render/stage_one_casters.hpp: material_surfaces), props of the
    // renderer the shade pass draws: an alpha-tested one's fragments discarded where its test does not
    // keep them, a textured one's coloured by its texture (render/base_colour_texture.hpp).
    void SetMaterialSurfaces(const std::vector<CasterActor>& surfaces);
    void SetShadePass(vtkRenderPass* shade);
    void SetOutput(Output output);
    // What the shaded output paints over the shading (the lit mask never has an overlay); ramp: the
    // texels-per-pixel overlay's colours at even steps over its positions 0..1 (texels_ramp_position),
    // joined linearly, 2 to kMaxRampStops of them. Throws std::invalid_argument for another count.
    static constexpr int kMaxRampStops = 16;
    void SetOverlay(MapOverlay overlay, const std::vector<glm::vec3>& ramp);

    void Render(const vtkRenderState* s) override;
    void ReleaseGraphicsResources(vtkWindow* w) override;
    bool PreReplaceShaderValues(std::string& vertex, std::string& geometry, std::string& fragment,
                                vtkAbstractMapper* mapper, vtkProp* prop) override;
    bool PostReplaceShaderValues(std::string& vertex, std::string& geometry, std::string& fragment,
                                 vtkAbstractMapper* mapper, vtkProp* prop) override;
    bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
                             vtkOpenGLVertexArrayObject* vao) override;
    vtkMTimeType GetShaderStageMTime() override { return stage_time_.GetMTime(); }

protected:
    ShadowMapPass();
    ~ShadowMapPass() override;

private:
    enum class Stage { depth, camera_depth, shade };  // camera_depth: VTK's own shaders, for contact shadows
    void enter(Stage stage);
    void prepare_targets(vtkOpenGLRenderWindow* window);
    void render_depth(const vtkRenderState* s, vtkOpenGLRenderWindow* window);
    void render_map_depth(const vtkRenderState* depth_state, vtkOpenGLState* gl, int map);
    void render_camera_depth(const vtkRenderState* s, vtkOpenGLRenderWindow* window);
    void render_shaded(const vtkRenderState* s);
    void casters_per_map();
    void prepare_alpha_textures(vtkOpenGLRenderWindow* window);
    // The alpha test of one of map_casters_' or alpha_surfaces_' actors, or null.
    const AlphaTest* alpha_of(vtkProp* prop) const;
    vtkTextureObject* alpha_texture(const AlphaTest* test) const;
    void prepare_page_textures(vtkOpenGLRenderWindow* window);
    bool paged() const { return setup_.selection.rule == MapSelection::Rule::pages; }

    Stage stage_ = Stage::shade;
    vtkTimeStamp stage_time_;
    Output output_ = Output::shaded;
    MapOverlay overlay_ = MapOverlay::none;
    std::vector<glm::vec3> ramp_{glm::vec3(0.0f), glm::vec3(1.0f)};
    ShadowSetup setup_;  // no maps until SetSetup: everything lit
    int drawn_map_ = 0;  // stage 1: the map whose tile is being drawn
    ShadowLookup lookup_;
    Light light_;
    std::vector<glm::vec3> taps_;  // the filter's taps as (offset, weight); empty for vsm, evsm
    ShadingFrame frame_;
    glm::ivec2 image_origin_{0};  // stage 2: the renderer's lower-left corner in the window
    int image_height_ = 0;        // and its height in pixels
    int resolution_ = 1024;
    std::vector<vtkProp*> casters_;
    WorldTriangles caster_triangles_;
    std::vector<bool> casts_per_object_;
    // Per map: its casters as triangles (split, or alpha-tested: render/stage_one_casters.hpp), or none:
    // the props. Each alpha test's texture, made once per context.
    std::vector<std::vector<CasterActor>> map_casters_;
    std::vector<CasterActor> alpha_surfaces_;
    BaseColourTextures base_colours_;  // the textured ones' textures
    // Held by their tests (which a texture's test keeps alive: no other test can take its address).
    std::vector<std::pair<std::shared_ptr<const AlphaTest>, vtkSmartPointer<vtkTextureObject>>> alpha_textures_;
    vtkSmartPointer<vtkRenderPass> shade_;
    vtkSmartPointer<vtkOpaquePass> depth_pass_;
    vtkSmartPointer<vtkOpenGLFramebufferObject> fbo_;
    vtkSmartPointer<vtkTextureObject> depth_, colour_;
    DepthEncoding allocated_encoding_ = DepthEncoding::float32;  // depth_'s internal format
    // Rule::pages: the page table (GL_R32I, pages_per_side x levels * pages_per_side) and each map's
    // slot (GL_RGBA32F, maps x 2), uploaded once per setup.
    vtkSmartPointer<vtkTextureObject> page_table_, page_slots_;
    bool page_textures_current_ = false;
    std::optional<ContactDepthImage> contact_image_;  // while the lookup's contact shadows are on
};

}  // namespace shadowlab
