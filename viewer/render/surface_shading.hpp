#pragma once
// How the Camera view colours a surface, shared by both GPU passes so that a map's shadow and a
// volume's look alike. Diffuse shading keeps the form; a shadow is told apart from a surface that
// merely faces away from the light by its hue as well as its value:
//   facing the light, lit:       ambient + diffuse · cos θ
//   facing the light, shadowed:  (ambient + diffuse · cos θ) · kShadowTint   (darker, blue-violet)
//   facing away from the light:  ambient       (neutral grey, whatever the shadow test says: it is
//                                               dark because of its orientation, not a caster)
// θ is the angle between the seen side's normal and the direction toward the light; ambient and
// diffuse are VTK's ambientColor and diffuseColor (albedo times the actor's coefficients). The tint
// fades in over the first few degrees toward the light, so that the terminator shows no seam. A lit
// mask instead writes white where lit and black where shadowed.
#include <string>
#include <glm/glm.hpp>

class vtkShaderProgram;

namespace shadowlab {

// A shadow's colour factor: about half the value (as dark as the old dimming by 0.45 to 0.5, which
// reads as shadow) and blue-violet, the colour of the skylight that still reaches a shadow.
inline constexpr glm::vec3 kShadowTint{0.42f, 0.40f, 0.66f};

// The light and the eye in the coordinates the actors are drawn in.
struct ShadingFrame {
    glm::vec4 light{0.0f, -1.0f, 0.0f, 0.0f};  // (direction it travels, 0) or (position, 1)
    glm::vec3 eye{0.0f};
};

// Vertex shader: passes the world position (vertexMC: our actors hold world coordinates) on as
// `surfaceWorldVSOutput`.
void pass_world_position(std::string& vertex);
// Fragment shader: declares the uniforms and functions below at //VTK::Light::Dec:
//   vec3 surfaceSeenNormal(vec3 p)   the normal of the side the camera sees (derivatives: call it
//                                     in uniform control flow)
//   vec3 surfaceAlongLight(vec3 p)   the unit direction the light travels at p
//   vec4 surfaceColour(vec3 ambient, vec3 diffuse, float opacity, vec3 p, vec3 n, float lit)
//                                     the colour above (lit: 1 lit, 0 shadowed), called after VTK's
//                                     own lighting with VTK's ambientColor, diffuseColor, opacity
void declare_surface_shading(std::string& fragment);
// The uniforms; false when one is missing.
bool set_surface_shading_uniforms(vtkShaderProgram* program, const ShadingFrame& frame, bool lit_mask);

}  // namespace shadowlab
