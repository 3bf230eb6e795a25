#include "render/contact_depth_image.hpp"

#include <algorithm>
#include <iterator>
#include <glm/gtc/type_ptr.hpp>
#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "render/depth_texture.hpp"

namespace shadowlab {
namespace {

// VTK's matrices hold rows; GLM's columns.
glm::dmat4 from_vtk(vtkMatrix4x4* m) {
    glm::dmat4 out;
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) out[column][row] = m->GetElement(row, column);
    return out;
}

}  // namespace

void ContactDepthImage::prepare(vtkRenderer* renderer, vtkOpenGLRenderWindow* window) {
    vtkCamera* camera = renderer->GetActiveCamera();
    const glm::dmat4 clip_from_world =
        from_vtk(camera->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1.0, 1.0));
    clip_from_world_ = glm::mat4(clip_from_world);
    world_from_clip_ = glm::mat4(glm::inverse(clip_from_world));
    eye_ = glm::vec3(glm::make_vec3(camera->GetPosition()));
    view_axis_ = glm::vec3(glm::normalize(glm::make_vec3(camera->GetDirectionOfProjection())));
    renderer->GetTiledSizeAndOrigin(&image_size_.x, &image_size_.y, &image_origin_.x, &image_origin_.y);

    const int* size = window->GetSize();
    if (depth_ && depth_->GetContext() == window && depth_->GetWidth() == static_cast<unsigned>(size[0]) &&
        depth_->GetHeight() == static_cast<unsigned>(size[1]))
        return;
    release(window);
    depth_ = depth_texture(window, size[0], size[1], vtkTextureObject::Float32);
    colour_ = completing_colour_texture(window, size[0], size[1]);
    fbo_ = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    fbo_->SetContext(window);
}

void ContactDepthImage::begin_drawing(vtkOpenGLState* gl) {
    gl->PushFramebufferBindings();
    fbo_->Bind();
    fbo_->AddColorAttachment(0, colour_);
    fbo_->AddDepthAttachment(depth_);
    fbo_->ActivateDrawBuffer(0);
    gl->vtkglDepthMask(GL_TRUE);
    gl->vtkglClearDepth(1.0);
    gl->vtkglClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    gl->vtkglEnable(GL_DEPTH_TEST);
    gl->vtkglDepthFunc(GL_LEQUAL);
}

vtkOpenGLFramebufferObject* ContactDepthImage::framebuffer() const { return fbo_; }

void ContactDepthImage::end_drawing(vtkOpenGLState* gl) { gl->PopFramebufferBindings(); }

void ContactDepthImage::activate() { depth_->Activate(); }
void ContactDepthImage::deactivate() { depth_->Deactivate(); }

bool ContactDepthImage::set_uniforms(ProgramUniforms& program, const ContactShadow& contact) const {
    glm::mat4 clip_from_world = clip_from_world_, world_from_clip = world_from_clip_;  // the setter takes a float*
    const bool found[] = {
        program.SetUniformi("shadowContactDepth", depth_->GetTextureUnit()),
        program.SetUniformMatrix4x4v("shadowContactClipFromWorld", 1, glm::value_ptr(clip_from_world)),
        program.SetUniformMatrix4x4v("shadowContactWorldFromClip", 1, glm::value_ptr(world_from_clip)),
        program.SetUniform3f("shadowContactEye", glm::value_ptr(eye_)),
        program.SetUniform3f("shadowContactViewAxis", glm::value_ptr(view_axis_)),
        program.SetUniform2i("shadowContactImageOrigin", glm::value_ptr(image_origin_)),
        program.SetUniform2i("shadowContactImageSize", glm::value_ptr(image_size_)),
        program.SetUniformf("shadowContactLength", static_cast<float>(contact.length)),
        program.SetUniformi("shadowContactSteps", contact.steps),
        program.SetUniformf("shadowContactThickness", static_cast<float>(contact.thickness))};
    return std::all_of(std::begin(found), std::end(found), [](bool f) { return f; });  // each set, even past a miss
}

void ContactDepthImage::release(vtkWindow* window) {
    if (fbo_) fbo_->ReleaseGraphicsResources(window);
    if (depth_) depth_->ReleaseGraphicsResources(window);
    if (colour_) colour_->ReleaseGraphicsResources(window);
    fbo_ = nullptr;
    depth_ = colour_ = nullptr;
}

}  // namespace shadowlab
