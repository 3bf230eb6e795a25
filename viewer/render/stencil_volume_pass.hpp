#pragma once
// Stencil shadows on the GPU (Everitt and Kilgard 2002, "Practical and Robust Stenciled Shadow
// Volumes"): our own render pass, with real stencil operations.
//
// 1. The scene through `scene` (normally a vtkRenderStepsPass): lit, writing depth.
// 2. The stencil polygons with colour and depth writes off and the depth test on, both faces in
//    one draw (glStencilOpSeparate): z-pass counts front +1 / back -1 where the depth test passes,
//    z-fail back +1 / front -1 where it fails; `cover` (planar shadows) sets 1 where it passes.
//    Vertices at infinity (w = 0) go through as they are; GL_DEPTH_CLAMP stands in for the
//    infinite far plane (they land at depth 1) and a clip distance keeps the near plane.
// 3. A full-viewport quad darkens the scene's pixels whose stencil is not 0.
// The render window must have a stencil buffer: vtkRenderWindow::SetStencilCapable(1) before its
// first render.
#include <vector>
#include <vtkRenderPass.h>
#include <vtkSmartPointer.h>

#include "techniques/geometry_result.hpp"

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;

namespace shadowlab {

class StencilVolumePass : public vtkRenderPass {
public:
    static StencilVolumePass* New();
    vtkTypeMacro(StencilVolumePass, vtkRenderPass);

    // What step 3 leaves: the lit colour dimmed where the stencil is set, or black there (the
    // scene drawn white: a lit mask).
    enum class Output { shaded, lit_mask };

    // World-space polygons (homogeneous, counter-clockwise seen from outside for the volume rules).
    void SetPolygons(const std::vector<HomogeneousPolygon>& polygons, StencilRule rule);
    void SetScenePass(vtkRenderPass* scene);
    void SetOutput(Output output);

    void Render(const vtkRenderState* s) override;
    void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
    StencilVolumePass();
    ~StencilVolumePass() override;

private:
    vtkShaderProgram* prepare(vtkOpenGLRenderWindow* window);  // nullptr when it does not compile
    void count(const vtkRenderState* s, vtkOpenGLState* gl, vtkShaderProgram* program);
    void darken(vtkOpenGLState* gl, vtkShaderProgram* program);

    std::vector<float> corners_;  // x, y, z, w per triangle corner: the polygons as fans, then a quad
    int polygon_corners_ = 0;
    bool uploaded_ = false;
    StencilRule rule_ = StencilRule::zfail;
    Output output_ = Output::shaded;
    vtkSmartPointer<vtkRenderPass> scene_;
    vtkSmartPointer<vtkOpenGLBufferObject> buffer_;
    vtkSmartPointer<vtkOpenGLVertexArrayObject> vao_;
};

}  // namespace shadowlab
