#include "render/surface_shading.hpp"

#include <string>
#include <glm/gtc/type_ptr.hpp>
#include <vtkShaderProgram.h>

namespace shadowlab {
namespace {

std::string glsl_vec3(const glm::vec3& v) {
    return "vec3(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

// The shading of surface_shading.hpp; the seen normal from derivatives, as VTK takes it for meshes
// without normals (ours), so that faces stay flat and the shadow test and the shading agree.
constexpr const char* kShadingFunctions = R"(
uniform vec4 surfaceLight;  // (direction it travels, 0) for a directional light, (position, 1) otherwise
uniform vec3 surfaceEye;
uniform int surfaceLitMask;
in vec4 surfaceWorldVSOutput;
vec3 surfaceSeenNormal(vec3 p) {
  vec3 n = normalize(cross(dFdx(p), dFdy(p)));
  return dot(n, surfaceEye - p) < 0.0 ? -n : n;
}
vec3 surfaceAlongLight(vec3 p) { return surfaceLight.w == 0.0 ? normalize(surfaceLight.xyz) : normalize(p - surfaceLight.xyz); }
vec4 surfaceColour(vec3 ambient, vec3 diffuse, float opacity, vec3 p, vec3 n, float lit) {
  if (surfaceLitMask == 1) return vec4(vec3(lit), 1.0);
  float cosine = dot(n, -surfaceAlongLight(p));
  float shadowed = (1.0 - lit) * smoothstep(0.0, 0.1, cosine);
  return vec4((ambient + diffuse * max(cosine, 0.0)) * mix(vec3(1.0), shadowTint, shadowed), opacity);
}
)";

}  // namespace

void pass_world_position(std::string& vertex) {
    vtkShaderProgram::Substitute(vertex, "//VTK::PositionVC::Dec",
                                 "//VTK::PositionVC::Dec\nout vec4 surfaceWorldVSOutput;\n", false);
    vtkShaderProgram::Substitute(vertex, "//VTK::PositionVC::Impl",
                                 "//VTK::PositionVC::Impl\n  surfaceWorldVSOutput = vertexMC;\n", false);
}

void declare_surface_shading(std::string& fragment) {
    const std::string tint = "const vec3 shadowTint = " + glsl_vec3(kShadowTint) + ";\n";
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Dec", "//VTK::Light::Dec\n" + tint + kShadingFunctions,
                                 false);
}

bool set_surface_shading_uniforms(vtkShaderProgram* program, const ShadingFrame& frame, bool lit_mask) {
    const bool light = program->SetUniform4f("surfaceLight", glm::value_ptr(frame.light));
    const bool eye = program->SetUniform3f("surfaceEye", glm::value_ptr(frame.eye));
    const bool mask = program->SetUniformi("surfaceLitMask", lit_mask ? 1 : 0);
    return light && eye && mask;
}

}  // namespace shadowlab
