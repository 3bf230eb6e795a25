#include "render/stencil_volume_pass.hpp"

#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLBufferObject.h>
#include <vtkOpenGLCamera.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLRenderer.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkOpenGLVertexArrayObject.h>
#include <vtkOpaquePass.h>
#include <vtkOverlayPass.h>
#include <vtkRenderState.h>
#include <vtkRenderStepsPass.h>
#include <vtkShaderProgram.h>
#include <vtk_glew.h>

#include "render/glsl_source.hpp"

namespace shadowlab {
namespace {

// The stencil operations per rule (Everitt and Kilgard 2002, section 4: z-fail; Heidmann: z-pass).
void set_stencil_ops(vtkOpenGLState* gl, StencilRule rule) {
    switch (rule) {
        case StencilRule::zfail:
            gl->vtkglStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
            gl->vtkglStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
            break;
        case StencilRule::zpass:
            gl->vtkglStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
            gl->vtkglStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
            break;
        case StencilRule::cover: gl->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE); break;
    }
}

// Makes sure the bound draw framebuffer has a stencil attachment; false when it cannot. VTK 9.1
// allocates its render framebuffer's depth texture with stencil bits when the window is stencil
// capable but attaches it as depth only: that texture is attached as the stencil buffer too.
bool attach_stencil_buffer() {
    GLint type = GL_NONE, bits = 0, name = 0;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_STENCIL_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_NONE) return true;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_TEXTURE) return false;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &bits);
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    if (bits <= 0) return false;
    // Any texture target: the window's textures are multisampled when it is (the Qt widget's are).
    glFramebufferTexture(GL_DRAW_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, static_cast<GLuint>(name), 0);
    if (glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) return true;
    glFramebufferTexture(GL_DRAW_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, 0, 0);  // as it was
    return false;
}

}  // namespace

vtkStandardNewMacro(StencilVolumePass);

StencilVolumePass::StencilVolumePass()
    : lit_scene_(vtkSmartPointer<vtkRenderStepsPass>::New()),
      shadowed_scene_(vtkSmartPointer<vtkOpaquePass>::New()),
      overlay_(vtkSmartPointer<vtkOverlayPass>::New()) {
    lit_scene_->SetOverlayPass(nullptr);
}

StencilVolumePass::~StencilVolumePass() = default;

void StencilVolumePass::SetPolygons(const std::vector<HomogeneousPolygon>& polygons, StencilRule rule) {
    corners_.clear();
    for (const HomogeneousPolygon& p : polygons)
        for (size_t i = 1; i + 1 < p.size(); ++i)
            for (const glm::dvec4& v : {p[0], p[i], p[i + 1]})
                for (int c = 0; c < 4; ++c) corners_.push_back(static_cast<float>(v[c]));
    rule_ = rule;
    uploaded_ = false;
    Modified();
}

void StencilVolumePass::SetLight(const glm::dvec4& light, const glm::dvec3& eye) {
    frame_ = {.light = glm::vec4(light), .eye = glm::vec3(eye)};
    Modified();
}

void StencilVolumePass::SetOutput(Output output) {
    output_ = output;
    Modified();
}

void StencilVolumePass::SetTexturedSurfaces(const std::vector<CasterActor>& surfaces) {
    base_colours_.set_surfaces(surfaces);
    Modified();
}

void StencilVolumePass::Render(const vtkRenderState* s) {
    auto* window = static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
    base_colours_.prepare(window);
    PreRender(s);
    lit_ = 1.0f;
    lit_scene_->Render(s);  // 1: the scene, lit, writing depth
    base_colours_.unbind();
    NumberOfRenderedProps = lit_scene_->GetNumberOfRenderedProps();
    if (vtkShaderProgram* program = corners_.empty() ? nullptr : prepare(window)) {
        if (attach_stencil_buffer()) {
            vtkOpenGLState* gl = window->GetState();
            vtkOpenGLState::ScopedglEnableDisable stencil_test(gl, GL_STENCIL_TEST);
            vtkOpenGLState::ScopedglEnableDisable depth_test(gl, GL_DEPTH_TEST);
            vtkOpenGLState::ScopedglEnableDisable blend(gl, GL_BLEND);
            vtkOpenGLState::ScopedglEnableDisable cull(gl, GL_CULL_FACE);
            vtkOpenGLState::ScopedglDepthMask depth_mask(gl);
            vtkOpenGLState::ScopedglColorMask colour_mask(gl);
            vtkOpenGLState::ScopedglDepthFunc depth_func(gl);
            // The renderer's own box of the window (a letterboxed panel's is smaller than the
            // window): the stencil is cleared, counted and read there only.
            vtkOpenGLState::ScopedglViewport viewport(gl);
            vtkOpenGLState::ScopedglScissor scissor_box(gl);
            vtkOpenGLState::ScopedglEnableDisable scissor(gl, GL_SCISSOR_TEST);
            int width = 0, height = 0, x = 0, y = 0;
            s->GetRenderer()->GetTiledSizeAndOrigin(&width, &height, &x, &y);
            gl->vtkglViewport(x, y, width, height);
            gl->vtkglScissor(x, y, width, height);
            gl->vtkglEnable(GL_SCISSOR_TEST);
            count(s, gl, program);
            shade_shadowed(s, gl);
            gl->vtkglStencilFunc(GL_ALWAYS, 0, ~0u);
            gl->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        } else {
            vtkWarningMacro(
                "the render window has no stencil buffer (SetStencilCapable(1) before its first render): no shadows");
        }
    }
    PostRender(s);
    overlay_->Render(s);  // 4: the captions over it all
}

vtkShaderProgram* StencilVolumePass::prepare(vtkOpenGLRenderWindow* window) {
    const std::string vertex(glsl_source("stencil_volume_vs")), fragment(glsl_source("stencil_volume_fs"));
    vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(vertex.c_str(), fragment.c_str(), "");
    if (!program) return nullptr;
    if (!vao_) {
        vao_ = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
        buffer_ = vtkSmartPointer<vtkOpenGLBufferObject>::New();
        buffer_->SetType(vtkOpenGLBufferObject::ArrayBuffer);
        uploaded_ = false;
    }
    if (!uploaded_) {
        vao_->Bind();
        buffer_->Upload(corners_, vtkOpenGLBufferObject::ArrayBuffer);
        vao_->AddAttributeArray(program, buffer_, "volumePosition", 0, 4 * sizeof(float), VTK_FLOAT, 4, false);
        vao_->Release();
        uploaded_ = true;
    }
    return program;
}

// 2: the polygons into the stencil buffer only.
void StencilVolumePass::count(const vtkRenderState* s, vtkOpenGLState* gl, vtkShaderProgram* program) {
    vtkMatrix4x4 *world_to_view, *view_to_clip, *world_to_clip;
    vtkMatrix3x3* normals;
    auto* camera = static_cast<vtkOpenGLCamera*>(s->GetRenderer()->GetActiveCamera());
    camera->GetKeyMatrices(s->GetRenderer(), world_to_view, normals, view_to_clip, world_to_clip);
    program->SetUniformMatrix("worldToClip", world_to_clip);

    gl->vtkglStencilMask(~0u);
    glClearStencil(0);
    gl->vtkglClear(GL_STENCIL_BUFFER_BIT);
    gl->vtkglEnable(GL_STENCIL_TEST);
    gl->vtkglStencilFunc(GL_ALWAYS, 1, ~0u);
    set_stencil_ops(gl, rule_);
    gl->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl->vtkglDepthMask(GL_FALSE);
    gl->vtkglEnable(GL_DEPTH_TEST);
    gl->vtkglDepthFunc(rule_ == StencilRule::cover ? GL_LEQUAL : GL_LESS);
    gl->vtkglDisable(GL_CULL_FACE);
    gl->vtkglDisable(GL_BLEND);
    // Volume faces a few depth units behind what they touch, so that a lit caster's own front cap
    // counts as behind it (as the CPU count has a face within 1e-5 of the depth); no slope term,
    // which would push the quads seen edge-on far behind the ground they cross. Planar shadows
    // in front of their plane.
    glEnable(GL_POLYGON_OFFSET_FILL);
    if (rule_ == StencilRule::cover)
        glPolygonOffset(-1.0f, -1.0f);
    else
        glPolygonOffset(0.0f, 8.0f);
    glEnable(GL_DEPTH_CLAMP);
    glEnable(GL_CLIP_DISTANCE0);
    vao_->Bind();
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(corners_.size() / 4));
    vao_->Release();
    glDisable(GL_CLIP_DISTANCE0);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_POLYGON_OFFSET_FILL);
}

// 3: the scene's opaque geometry shaded as shadowed where the stencil is not 0, on the very
// fragments step 1 drew (the same shader on the same geometry gives the same depth: GL_LEQUAL
// passes them and nothing behind).
void StencilVolumePass::shade_shadowed(const vtkRenderState* s, vtkOpenGLState* gl) {
    gl->vtkglStencilFunc(GL_NOTEQUAL, 0, ~0u);
    gl->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    gl->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl->vtkglDepthFunc(GL_LEQUAL);
    lit_ = 0.0f;
    shadowed_scene_->Render(s);
    base_colours_.unbind();
    lit_ = 1.0f;
}

bool StencilVolumePass::PreReplaceShaderValues(std::string& vertex, std::string&, std::string& fragment,
                                               vtkAbstractMapper*, vtkProp* prop) {
    pass_world_position(vertex);
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Dec", "//VTK::Light::Dec\nuniform float surfaceLit;\n",
                                 false);
    declare_surface_shading(fragment);
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Impl", std::string(glsl_source("stencil_shade")), false);
    if (base_colours_.textured(prop)) {  // declared last, so that the texture coordinates come first
        BaseColourTextures::replace_colour(fragment);
        pass_texture_coordinates(vertex, fragment);
    }
    return true;
}

bool StencilVolumePass::SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop,
                                            vtkOpenGLVertexArrayObject*) {
    const bool lit = program->SetUniformf("surfaceLit", lit_);
    const bool textured = base_colours_.bind(prop, program);
    return set_surface_shading_uniforms(program, frame_, output_ == Output::lit_mask) && lit && textured;
}

void StencilVolumePass::ReleaseGraphicsResources(vtkWindow* w) {
    base_colours_.release(w);
    lit_scene_->ReleaseGraphicsResources(w);
    shadowed_scene_->ReleaseGraphicsResources(w);
    overlay_->ReleaseGraphicsResources(w);
    if (vao_) vao_->ReleaseGraphicsResources();
    if (buffer_) buffer_->ReleaseGraphicsResources();
    vao_ = nullptr;
    buffer_ = nullptr;
    uploaded_ = false;
}

}  // namespace shadowlab
