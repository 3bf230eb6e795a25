#include "render/base_colour_texture.hpp"

#include <algorithm>
#include <stdexcept>
#include <glm/gtc/type_ptr.hpp>
#include <vtkActor.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "render/glsl_source.hpp"

namespace shadowlab {
namespace {

vtkSmartPointer<vtkTextureObject> colour_texture_object(const ColourTexture& colour, vtkOpenGLRenderWindow* window) {
    auto texture = vtkSmartPointer<vtkTextureObject>::New();
    texture->SetContext(window);
    texture->SetInternalFormat(GL_SRGB8_ALPHA8);
    texture->SetFormat(GL_RGBA);
    texture->SetDataType(GL_UNSIGNED_BYTE);
    texture->SetGenerateMipmap(true);
    texture->SetMinificationFilter(vtkTextureObject::LinearMipmapLinear);
    texture->SetMagnificationFilter(vtkTextureObject::Linear);
    texture->SetWrapS(vtkTextureObject::Repeat);
    texture->SetWrapT(vtkTextureObject::Repeat);
    if (!texture->Create2DFromRaw(colour.width, colour.height, 4, VTK_UNSIGNED_CHAR,
                                  const_cast<std::uint8_t*>(colour.srgb_rgba.data())))
        throw std::runtime_error("base colour texture " + colour.file + " could not be made");
    return texture;
}

}  // namespace

void BaseColourTextures::set_surfaces(const std::vector<CasterActor>& surfaces) { surfaces_ = surfaces; }

const BaseColour* BaseColourTextures::textured(vtkProp* prop) const {
    const auto found = std::find_if(surfaces_.begin(), surfaces_.end(),
                                    [prop](const CasterActor& surface) { return surface.actor.GetPointer() == prop; });
    return found != surfaces_.end() ? found->textured.get() : nullptr;
}

void BaseColourTextures::replace_colour(std::string& fragment) {
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Dec",
                                 "//VTK::Light::Dec\n" + std::string(glsl_source("base_colour")), false);
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Impl",
                                 "//VTK::Light::Impl\n  {\n    vec3 shown = surfaceBaseColourShown();\n"
                                 "    ambientColor *= shown;\n    diffuseColor *= shown;\n  }\n",
                                 false);
}

void BaseColourTextures::prepare(vtkOpenGLRenderWindow* window) {
    unbind();
    std::erase_if(made_, [&](const auto& made) {
        const bool drawn = std::any_of(surfaces_.begin(), surfaces_.end(), [&](const CasterActor& surface) {
            return surface.textured && surface.textured->texture == made.first;
        });
        return made.second->GetContext() != window || !drawn;
    });
    for (const CasterActor& surface : surfaces_)
        if (surface.textured && !texture_of(*surface.textured))
            made_.emplace_back(surface.textured->texture, colour_texture_object(*surface.textured->texture, window));
}

vtkTextureObject* BaseColourTextures::texture_of(const BaseColour& colour) const {
    const auto found =
        std::find_if(made_.begin(), made_.end(), [&](const auto& made) { return made.first == colour.texture; });
    return found != made_.end() ? found->second.GetPointer() : nullptr;
}

bool BaseColourTextures::bind(vtkProp* prop, vtkShaderProgram* program) {
    unbind();
    const BaseColour* colour = textured(prop);
    if (!colour) return true;
    bound_ = texture_of(*colour);
    if (!bound_) return false;  // not prepared
    bound_->Activate();
    const glm::vec3 factor(colour->factor);
    return program->SetUniformi("surfaceBaseColour", bound_->GetTextureUnit()) &&
           program->SetUniform3f("surfaceBaseColourFactor", glm::value_ptr(factor));
}

void BaseColourTextures::unbind() {
    if (bound_) bound_->Deactivate();
    bound_ = nullptr;
}

void BaseColourTextures::release(vtkWindow* window) {
    unbind();
    for (auto& [colour, texture] : made_) texture->ReleaseGraphicsResources(window);
    made_.clear();
}

}  // namespace shadowlab
