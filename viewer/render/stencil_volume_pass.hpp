#pragma once
// Stencil shadows on the GPU (Everitt and Kilgard 2002, "Practical and Robust Stenciled Shadow
// Volumes"): our own render pass, with real stencil operations.
//
// 1. The scene, lit (render/surface_shading.hpp, as the shadow-map pass shades it), writing depth.
// 2. The stencil polygons with colour and depth writes off and the depth test on, both faces in
//    one draw (glStencilOpSeparate): z-pass counts front +1 / back -1 where the depth test passes,
//    z-fail back +1 / front -1 where it fails; `cover` (planar shadows) sets 1 where it passes.
//    Vertices at infinity (w = 0) go through as they are; GL_DEPTH_CLAMP stands in for the
//    infinite far plane (they land at depth 1) and a clip distance keeps the near plane.
// 3. The scene's opaque geometry again, shaded as shadowed, where the stencil is not 0 and the depth
//    equals step 1's: the classic second pass, so that a shadowed surface gets the same colour as
//    under the map pass (a dimming quad could not tell a shadow from a surface facing away).
// 4. The overlay (captions), last, so that step 3 never paints over it.
// The render window must have a stencil buffer: vtkRenderWindow::SetStencilCapable(1) before its
// first render.
#include <vector>
#include <glm/glm.hpp>
#include <vtkOpenGLRenderPass.h>
#include <vtkSmartPointer.h>

#include "render/base_colour_texture.hpp"
#include "render/surface_shading.hpp"
#include "techniques/geometry_result.hpp"

class vtkOpaquePass;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkOpenGLVertexArrayObject;
class vtkOverlayPass;
class vtkRenderStepsPass;
class vtkShaderProgram;

namespace shadowlab {

class StencilVolumePass : public vtkOpenGLRenderPass {
public:
    static StencilVolumePass* New();
    vtkTypeMacro(StencilVolumePass, vtkOpenGLRenderPass);

    // What the passes write: the surface shading, shadow tinted where the stencil is set, or white
    // where lit and black there (a lit mask).
    enum class Output { shaded, lit_mask };

    // World-space polygons (homogeneous, counter-clockwise seen from outside for the volume rules).
    void SetPolygons(const std::vector<HomogeneousPolygon>& polygons, StencilRule rule);
    // light: (direction it travels, 0) or (position, 1); eye: the camera's position.
    void SetLight(const glm::dvec4& light, const glm::dvec3& eye);
    void SetOutput(Output output);
    // The surfaces with a material (render/stage_one_casters.hpp: material_surfaces): the textured ones
    // coloured by their texture (render/base_colour_texture.hpp); the alpha-tested ones drawn whole.
    void SetTexturedSurfaces(const std::vector<CasterActor>& surfaces);

    void Render(const vtkRenderState* s) override;
    void ReleaseGraphicsResources(vtkWindow* w) override;
    bool PreReplaceShaderValues(std::string& vertex, std::string& geometry, std::string& fragment,
                                vtkAbstractMapper* mapper, vtkProp* prop) override;
    bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
                             vtkOpenGLVertexArrayObject* vao) override;

protected:
    StencilVolumePass();
    ~StencilVolumePass() override;

private:
    vtkShaderProgram* prepare(vtkOpenGLRenderWindow* window);  // nullptr when it does not compile
    void count(const vtkRenderState* s, vtkOpenGLState* gl, vtkShaderProgram* program);
    void shade_shadowed(const vtkRenderState* s, vtkOpenGLState* gl);

    std::vector<float> corners_;  // x, y, z, w per triangle corner: the polygons as fans
    bool uploaded_ = false;
    StencilRule rule_ = StencilRule::zfail;
    Output output_ = Output::shaded;
    ShadingFrame frame_;
    float lit_ = 1.0f;  // what the scene's fragments are shaded as: 1 in step 1, 0 in step 3
    vtkSmartPointer<vtkRenderStepsPass> lit_scene_;  // step 1: VTK's steps without the overlay
    vtkSmartPointer<vtkOpaquePass> shadowed_scene_;  // step 3
    vtkSmartPointer<vtkOverlayPass> overlay_;        // step 4
    vtkSmartPointer<vtkOpenGLBufferObject> buffer_;
    vtkSmartPointer<vtkOpenGLVertexArrayObject> vao_;
    BaseColourTextures base_colours_;
};

}  // namespace shadowlab
