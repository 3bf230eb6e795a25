#include "render/shadow_map_pass.hpp"

#include <vtkObjectFactory.h>
#include <vtkOpaquePass.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLRenderer.h>
#include <vtkOpenGLState.h>
#include <vtkRenderState.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

namespace shadowlab {
namespace {

void to_floats(const glm::dmat4& m, float* out) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out[4 * c + r] = static_cast<float>(m[c][r]);
}

// (u, v, d) in [0,1] to OpenGL clip space [-1,1]: x' = 2x - w, the same for y and z.
glm::dmat4 uvz_to_clip() {
    glm::dmat4 m(2.0);
    m[3] = glm::dvec4(-1.0, -1.0, -1.0, 1.0);
    return m;
}

// Declarations for the lookup. The slope-scaled bias is the CPU's (metrics/shadow_error.hpp,
// slope_scaled_bias): the texel's world size across the light, 1 / (N σ_min(J)) with J = d(u, v)
// per world unit across the light, times 1 + tan θ (clamped to 10), θ between the seen side's
// normal and the light.
constexpr const char* kLookupDeclarations = R"(//VTK::Light::Dec
uniform sampler2D shadowDepth;
uniform mat4 shadowWorldToUvz;
uniform vec4 shadowLight;  // (direction, 0) for a directional light, (position, 1) otherwise
uniform vec3 shadowEye;
uniform float shadowBias;  // world units along the light; < 0: slope-scaled per fragment
uniform float shadowZBiasScale;
uniform int shadowResolution;
uniform int shadowLitMask;
in vec4 shadowWorldVSOutput;
vec3 shadowAlongLight(vec3 p) { return shadowLight.w == 0.0 ? shadowLight.xyz : normalize(p - shadowLight.xyz); }
vec2 shadowUv(vec3 p) { vec4 h = shadowWorldToUvz * vec4(p, 1.0); return h.xy / h.w; }
float shadowSlopeScaledBias(vec3 p) {
  vec3 l = shadowAlongLight(p);
  vec3 a = normalize(cross(l, abs(l.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  vec3 b = cross(l, a);
  float h = 1e-3 * (1.0 + length(p));
  vec2 uv = shadowUv(p);
  vec2 ja = (shadowUv(p + h * a) - uv) / h, jb = (shadowUv(p + h * b) - uv) / h;
  float t = dot(ja, ja) + dot(jb, jb), d = ja.x * jb.y - ja.y * jb.x;
  float smallest = 0.5 * (t - sqrt(max(t * t - 4.0 * d * d, 0.0)));  // σ_min²
  float texel = 1.0 / (float(shadowResolution) * sqrt(max(smallest, 1e-30)));
  vec3 n = normalize(cross(dFdx(p), dFdy(p)));
  if (dot(n, shadowEye - p) < 0.0) n = -n;  // the side the camera sees
  float c = dot(n, -l);
  float tanTheta = min(10.0, sqrt(max(0.0, 1.0 - c * c)) / max(c, 1e-6));
  return texel * (1.0 + tanTheta);
}
)";

// The lookup, after VTK's lighting: the nearest texel's depth against the fragment's, biased
// before the division by w; outside the map or behind its projection centre counts as lit.
constexpr const char* kLookup = R"(//VTK::Light::Impl
  {
    float lit = 1.0;
    vec3 p = shadowWorldVSOutput.xyz;
    vec4 sc = shadowWorldToUvz * vec4(p, 1.0);
    float bias = shadowBias >= 0.0 ? shadowBias : shadowSlopeScaledBias(p);
    if (sc.w > 0.0) {
      vec3 uvz = vec3(sc.xy, sc.z - shadowZBiasScale * bias) / sc.w;
      if (all(greaterThanEqual(uvz.xy, vec2(0.0))) && all(lessThanEqual(uvz.xy, vec2(1.0)))) {
        vec2 texel = (floor(uvz.xy * float(shadowResolution)) + 0.5) / float(shadowResolution);
        lit = uvz.z > texture(shadowDepth, texel).r ? 0.0 : 1.0;
      }
    }
    if (shadowLitMask == 1) gl_FragData[0] = vec4(vec3(lit), 1.0);
    else gl_FragData[0].rgb *= mix(0.45, 1.0, lit);
  }
)";

}  // namespace

vtkStandardNewMacro(ShadowMapPass);

ShadowMapPass::ShadowMapPass() : depth_pass_(vtkSmartPointer<vtkOpaquePass>::New()) { SetMap(glm::dmat4(1.0), 1.0, 1024); }

ShadowMapPass::~ShadowMapPass() = default;

void ShadowMapPass::SetMap(const glm::dmat4& world_to_uvz, double z_bias_scale, int resolution) {
    to_floats(world_to_uvz, world_to_uvz_);
    to_floats(uvz_to_clip() * world_to_uvz, world_to_clip_);
    z_bias_scale_ = static_cast<float>(z_bias_scale);
    resolution_ = resolution;
    Modified();
}

void ShadowMapPass::SetBias(double bias, const glm::dvec4& light, const glm::dvec3& eye) {
    bias_ = static_cast<float>(bias);
    for (int i = 0; i < 4; ++i) light_[i] = static_cast<float>(light[i]);
    for (int i = 0; i < 3; ++i) eye_[i] = static_cast<float>(eye[i]);
    Modified();
}

void ShadowMapPass::SetCasters(const std::vector<vtkProp*>& casters) {
    casters_ = casters;
    Modified();
}

void ShadowMapPass::SetShadePass(vtkRenderPass* shade) {
    shade_ = shade;
    Modified();
}

void ShadowMapPass::SetOutput(Output output) {
    output_ = output;
    Modified();
}

void ShadowMapPass::enter(Stage stage) {
    stage_ = stage;
    stage_time_.Modified();  // the mappers rebuild their shaders (from VTK's shader cache)
}

void ShadowMapPass::Render(const vtkRenderState* s) {
    NumberOfRenderedProps = 0;
    auto* window = static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
    prepare_targets(window);
    render_depth(s, window);
    render_shaded(s);
}

void ShadowMapPass::prepare_targets(vtkOpenGLRenderWindow* window) {
    if (depth_ && depth_->GetWidth() == static_cast<unsigned>(resolution_) && depth_->GetContext() == window) return;
    ReleaseGraphicsResources(window);
    depth_ = vtkSmartPointer<vtkTextureObject>::New();
    depth_->SetContext(window);
    depth_->SetMinificationFilter(vtkTextureObject::Nearest);
    depth_->SetMagnificationFilter(vtkTextureObject::Nearest);
    depth_->SetWrapS(vtkTextureObject::ClampToEdge);
    depth_->SetWrapT(vtkTextureObject::ClampToEdge);
    depth_->AllocateDepth(resolution_, resolution_, vtkTextureObject::Float32);
    colour_ = vtkSmartPointer<vtkTextureObject>::New();  // unused, but keeps the FBO complete everywhere
    colour_->SetContext(window);
    colour_->Allocate2D(resolution_, resolution_, 4, VTK_UNSIGNED_CHAR);
    fbo_ = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    fbo_->SetContext(window);
}

// Stage 1: the casters' depth under world_to_uvz.
void ShadowMapPass::render_depth(const vtkRenderState* s, vtkOpenGLRenderWindow* window) {
    vtkOpenGLState* gl = window->GetState();
    vtkOpenGLState::ScopedglViewport viewport(gl);
    vtkOpenGLState::ScopedglEnableDisable scissor(gl, GL_SCISSOR_TEST);
    gl->PushFramebufferBindings();
    fbo_->Bind();
    fbo_->AddColorAttachment(0, colour_);
    fbo_->AddDepthAttachment(depth_);
    fbo_->ActivateDrawBuffer(0);
    gl->vtkglDisable(GL_SCISSOR_TEST);
    gl->vtkglViewport(0, 0, resolution_, resolution_);
    gl->vtkglDepthMask(GL_TRUE);
    gl->vtkglClearDepth(1.0);
    gl->vtkglClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    gl->vtkglEnable(GL_DEPTH_TEST);
    gl->vtkglDepthFunc(GL_LEQUAL);
    glEnable(GL_DEPTH_CLAMP);

    enter(Stage::depth);
    vtkRenderState depth_state(s->GetRenderer());
    depth_state.SetPropArrayAndCount(casters_.data(), static_cast<int>(casters_.size()));
    depth_state.SetFrameBuffer(fbo_);
    PreRender(&depth_state);
    depth_pass_->Render(&depth_state);
    PostRender(&depth_state);

    glDisable(GL_DEPTH_CLAMP);
    gl->PopFramebufferBindings();
}

// Stage 2: the scene, each fragment looked up in the map.
void ShadowMapPass::render_shaded(const vtkRenderState* s) {
    if (!shade_) return;
    enter(Stage::shade);
    depth_->Activate();
    PreRender(s);
    shade_->Render(s);
    NumberOfRenderedProps = shade_->GetNumberOfRenderedProps();
    PostRender(s);
    depth_->Deactivate();
}

bool ShadowMapPass::PreReplaceShaderValues(std::string& vertex, std::string&, std::string& fragment,
                                           vtkAbstractMapper*, vtkProp*) {
    if (stage_ == Stage::depth) {
        vtkShaderProgram::Substitute(vertex, "//VTK::PositionVC::Dec",
                                     "//VTK::PositionVC::Dec\nuniform mat4 shadowWorldToClip;\n", false);
        return true;
    }
    vtkShaderProgram::Substitute(vertex, "//VTK::PositionVC::Dec", "//VTK::PositionVC::Dec\nout vec4 shadowWorldVSOutput;\n",
                                 false);
    vtkShaderProgram::Substitute(vertex, "//VTK::PositionVC::Impl",
                                 "//VTK::PositionVC::Impl\n  shadowWorldVSOutput = vertexMC;\n", false);
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Dec", kLookupDeclarations, false);
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Impl", kLookup, false);
    return true;
}

bool ShadowMapPass::PostReplaceShaderValues(std::string& vertex, std::string&, std::string&, vtkAbstractMapper*,
                                            vtkProp*) {
    // Our actors hold world coordinates (identity model matrix, no VBO shift): MC is world.
    if (stage_ == Stage::depth)
        vtkShaderProgram::Substitute(vertex, "gl_Position = MCDCMatrix * vertexMC;",
                                     "gl_Position = shadowWorldToClip * vertexMC;", true);
    return true;
}

bool ShadowMapPass::SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*,
                                        vtkOpenGLVertexArrayObject*) {
    if (stage_ == Stage::depth) return program->SetUniformMatrix4x4("shadowWorldToClip", world_to_clip_);
    program->SetUniformMatrix4x4("shadowWorldToUvz", world_to_uvz_);
    program->SetUniformi("shadowDepth", depth_->GetTextureUnit());
    program->SetUniform4f("shadowLight", light_);
    program->SetUniform3f("shadowEye", eye_);
    program->SetUniformf("shadowBias", bias_);
    program->SetUniformf("shadowZBiasScale", z_bias_scale_);
    program->SetUniformi("shadowResolution", resolution_);
    program->SetUniformi("shadowLitMask", output_ == Output::lit_mask ? 1 : 0);
    return true;
}

void ShadowMapPass::ReleaseGraphicsResources(vtkWindow* w) {
    if (shade_) shade_->ReleaseGraphicsResources(w);
    depth_pass_->ReleaseGraphicsResources(w);
    if (fbo_) fbo_->ReleaseGraphicsResources(w);
    if (depth_) depth_->ReleaseGraphicsResources(w);
    if (colour_) colour_->ReleaseGraphicsResources(w);
    fbo_ = nullptr;
    depth_ = colour_ = nullptr;
}

}  // namespace shadowlab
