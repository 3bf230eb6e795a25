#pragma once
// Textured materials on the GPU (scene/base_colour.hpp), for both passes' stage that shades the scene:
// each texture made once per context (GL_SRGB8_ALPHA8, so that a read is linear as glTF says; trilinear,
// repeated), bound around the draw of the actor that reads it, and the fragment shader's colour
// (glsl/base_colour.glsl) multiplied into VTK's ambient and diffuse colours before the pass shades them
// (render/surface_shading.hpp): shaded as the palette colours, the shadow tint on top.
#include <memory>
#include <string>
#include <vector>
#include <vtkSmartPointer.h>

#include "render/stage_one_casters.hpp"
#include "scene/base_colour.hpp"

class vtkOpenGLRenderWindow;
class vtkProp;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace shadowlab {

class BaseColourTextures {
public:
    // The surfaces (material_surfaces); those with a texture are the textured props.
    void set_surfaces(const std::vector<CasterActor>& surfaces);
    // The textured material a prop draws, or null.
    const BaseColour* textured(vtkProp* prop) const;
    // A textured prop's fragment shader (with its texture coordinates passed on: pass_texture_coordinates),
    // after the pass's own replacement of //VTK::Light::Impl: its colour multiplied in before the shading.
    static void replace_colour(std::string& fragment);
    // Before the stage: every texture made for this context (those of materials no longer drawn let go).
    void prepare(vtkOpenGLRenderWindow* window);
    // Before a prop's draw: its texture bound in place of the one before and its uniforms set (none for
    // a prop without a texture). False when a uniform is missing.
    bool bind(vtkProp* prop, vtkShaderProgram* program);
    // After the stage's last draw.
    void unbind();
    void release(vtkWindow* window);

private:
    vtkTextureObject* texture_of(const BaseColour& colour) const;

    std::vector<CasterActor> surfaces_;
    std::vector<std::pair<std::shared_ptr<const ColourTexture>, vtkSmartPointer<vtkTextureObject>>> made_;
    vtkTextureObject* bound_ = nullptr;
};

}  // namespace shadowlab
