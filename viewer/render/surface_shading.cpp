#include "render/surface_shading.hpp"

#include <string>
#include <glm/gtc/type_ptr.hpp>
#include <vtkShaderProgram.h>

#include "render/glsl_source.hpp"

namespace shadowlab {
namespace {

std::string glsl_vec3(const glm::vec3& v) {
    return "vec3(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

}  // namespace

void pass_world_position(std::string& vertex) {
    vtkShaderProgram::Substitute(vertex, "//VTK::PositionVC::Dec",
                                 "//VTK::PositionVC::Dec\nout vec4 surfaceWorldVSOutput;\n", false);
    vtkShaderProgram::Substitute(vertex, "//VTK::PositionVC::Impl",
                                 "//VTK::PositionVC::Impl\n  surfaceWorldVSOutput = vertexMC;\n", false);
}

void declare_surface_shading(std::string& fragment) {
    const std::string tint = "const vec3 shadowTint = " + glsl_vec3(kShadowTint) + ";\n";
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Dec",
                                 "//VTK::Light::Dec\n" + tint + std::string(glsl_source("surface_shading")), false);
}

bool set_surface_shading_uniforms(vtkShaderProgram* program, const ShadingFrame& frame, bool lit_mask) {
    const bool light = program->SetUniform4f("surfaceLight", glm::value_ptr(frame.light));
    const bool eye = program->SetUniform3f("surfaceEye", glm::value_ptr(frame.eye));
    const bool mask = program->SetUniformi("surfaceLitMask", lit_mask ? 1 : 0);
    return light && eye && mask;
}

}  // namespace shadowlab
