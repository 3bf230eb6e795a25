#pragma once
// A shader program's uniforms, set by name where the program reads them. A program compiled with
// some switches as constants (ShadowMapPass's program for a hard lookup) leaves uniforms that only
// the branches not taken read, which the GLSL compiler removes (PCSS's light size under a hard
// filter); OpenGL then has no location for them. Such a uniform is skipped and counts as found as
// long as a shader of the program names it: a name no shader holds is not found, so that a
// misspelt one still fails the pass. The setters are vtkShaderProgram's, under the same names.
#include <string>
#include <vtkShader.h>
#include <vtkShaderProgram.h>

namespace shadowlab {

class ProgramUniforms {
public:
    explicit ProgramUniforms(vtkShaderProgram* program) : program_(program) {}

    // clang-format off
    template <class... V> bool SetUniformi(const char* n, V... v) { return read(n) ? program_->SetUniformi(n, v...) : named(n); }
    template <class... V> bool SetUniformf(const char* n, V... v) { return read(n) ? program_->SetUniformf(n, v...) : named(n); }
    template <class... V> bool SetUniform2i(const char* n, V... v) { return read(n) ? program_->SetUniform2i(n, v...) : named(n); }
    template <class... V> bool SetUniform3f(const char* n, V... v) { return read(n) ? program_->SetUniform3f(n, v...) : named(n); }
    template <class... V> bool SetUniform4f(const char* n, V... v) { return read(n) ? program_->SetUniform4f(n, v...) : named(n); }
    template <class... V> bool SetUniform1iv(const char* n, V... v) { return read(n) ? program_->SetUniform1iv(n, v...) : named(n); }
    template <class... V> bool SetUniform1fv(const char* n, V... v) { return read(n) ? program_->SetUniform1fv(n, v...) : named(n); }
    template <class... V> bool SetUniform3fv(const char* n, V... v) { return read(n) ? program_->SetUniform3fv(n, v...) : named(n); }
    template <class... V> bool SetUniform4fv(const char* n, V... v) { return read(n) ? program_->SetUniform4fv(n, v...) : named(n); }
    template <class... V> bool SetUniformMatrix4x4v(const char* n, V... v) { return read(n) ? program_->SetUniformMatrix4x4v(n, v...) : named(n); }
    // clang-format on

private:
    bool read(const char* name) const { return program_->IsUniformUsed(name); }
    bool named(const char* name) const {
        for (vtkShader* shader : {program_->GetVertexShader(), program_->GetFragmentShader()})
            if (shader && shader->GetSource().find(name) != std::string::npos) return true;
        return false;
    }

    vtkShaderProgram* program_;
};

}  // namespace shadowlab
