#pragma once
// Contact shadows on the GPU (lookup/contact_shadow.hpp): the camera's depth image, the renderer's
// opaque props drawn from its own camera into a depth texture before stage 2, which marches in it
// (render/glsl/contact_shadow.glsl) as the CPU marches in the reference's visible points
// (reference/camera_depth_image.hpp). ShadowMapPass makes one only while its lookup's contact
// shadows are on: off, nothing is drawn or allocated.
#include <glm/glm.hpp>
#include <vtkSmartPointer.h>

#include "lookup/contact_shadow.hpp"
#include "render/program_uniforms.hpp"

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

namespace shadowlab {

class ContactDepthImage {
public:
    // The renderer's camera as it draws now (its matrices, in the setup's coordinates) and where its
    // image lies in the window; the texture sized to the window, in its context.
    void prepare(vtkRenderer* renderer, vtkOpenGLRenderWindow* window);
    // Draw into the depth texture (cleared to the far depth, depth test on) between these two; the
    // renderer's viewport places its image in the window-sized texture.
    void begin_drawing(vtkOpenGLState* gl);
    void end_drawing(vtkOpenGLState* gl);
    vtkOpenGLFramebufferObject* framebuffer() const;
    // Stage 2 reads the texture between these two.
    void activate();
    void deactivate();
    // The march's uniforms (contact_shadow.glsl), the texture's unit among them.
    bool set_uniforms(ProgramUniforms& program, const ContactShadow& contact) const;
    void release(vtkWindow* window);

private:
    glm::mat4 clip_from_world_{1.0f}, world_from_clip_{1.0f};
    glm::vec3 eye_{0.0f}, view_axis_{0.0f, 0.0f, -1.0f};
    glm::ivec2 image_origin_{0}, image_size_{0};  // the renderer's lower-left pixel in the window, its size
    vtkSmartPointer<vtkOpenGLFramebufferObject> fbo_;
    vtkSmartPointer<vtkTextureObject> depth_, colour_;
};

}  // namespace shadowlab
