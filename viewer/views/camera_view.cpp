// The Camera view: the scene as the camera sees it, shadowed on the GPU: by the method's own map
// (ShadowMapPass), or for a geometric technique by its polygons in the stencil buffer
// (StencilVolumePass): the shadow volume for `volumes`, and for `planar` the flattened casters
// drawn onto their plane (Blinn's projection shadows, the stencil keeping overlaps from darkening twice).
#include <vtkActor.h>
#include <vtkProperty.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>

#include "render/shadow_map_pass.hpp"
#include "render/stencil_volume_pass.hpp"
#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

// The light as both passes take it: (the direction it travels, 0) or (its position, 1).
glm::dvec4 pass_light(const Light& light) {
    return light.is_directional() ? glm::dvec4(light.direction, 0.0) : glm::dvec4(light.position, 1.0);
}

void install_map_pass(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options, vtkActor* casters,
                      const Light& light) {
    vtkNew<ShadowMapPass> pass;
    pass->SetSetup(relative_to(in.setup, in.scene.camera.position), in.resolution);
    pass->SetBias(in.bias, pass_light(light), glm::dvec3(0.0));  // the eye
    pass->SetCasters({casters});
    pass->SetShadePass(vtkNew<vtkRenderStepsPass>());
    pass->SetOutput(options.lit_mask ? ShadowMapPass::Output::lit_mask : ShadowMapPass::Output::shaded);
    renderer->SetPass(pass);
}

void install_stencil_pass(vtkRenderer* renderer, const GeometryResult& technique, const ViewOptions& options,
                          const glm::dvec3& origin, const Light& light) {
    vtkNew<StencilVolumePass> pass;
    std::vector<HomogeneousPolygon> local;
    for (const HomogeneousPolygon& p : technique.stencil) local.push_back(translated(p, -origin));
    pass->SetPolygons(local, technique.rule);
    pass->SetLight(pass_light(light), glm::dvec3(0.0));  // the eye
    pass->SetOutput(options.lit_mask ? StencilVolumePass::Output::lit_mask : StencilVolumePass::Output::shaded);
    renderer->SetPass(pass);
}

}  // namespace

// Drawn in camera-relative coordinates (the eye at 0): VTK and the GPU passes work in float32, which
// steps by 0.06 units a million units from the origin; near the eye it is as fine as anywhere.
ViewReport build_camera_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options) {
    const glm::dvec3 origin = in.scene.camera.position;
    glm::dmat4 local_from_world(1.0);
    local_from_world[3] = glm::dvec4(-origin, 1.0);
    Camera camera = in.scene.camera;
    camera.position -= origin;
    camera.target -= origin;
    Light light = in.scene.light;
    light.position -= origin;
    const std::vector<glm::dvec3> colours = object_colours(in.scene);
    std::vector<bool> not_casting(in.casters.size());
    for (size_t i = 0; i < in.casters.size(); ++i) not_casting[i] = !in.casters[i];
    auto casters = actor_for(triangles_polydata(in.triangles, in.casters, colours, local_from_world), glm::dvec3(1.0));
    auto others = actor_for(triangles_polydata(in.triangles, not_casting, colours, local_from_world), glm::dvec3(1.0));
    for (vtkActor* actor : {casters.Get(), others.Get()}) {  // the passes shade them (render/surface_shading.hpp)
        actor->GetProperty()->SetAmbient(0.35);
        actor->GetProperty()->SetDiffuse(0.75);
        actor->GetProperty()->BackfaceCullingOff();
        renderer->AddActor(actor);
    }
    place_scene_camera(renderer, camera);
    renderer->SetBackground(0.62, 0.74, 0.86);
    if (in.has_map())
        install_map_pass(renderer, in, options, casters, light);
    else
        install_stencil_pass(renderer, *in.geometry, options, origin, light);
    if (options.lit_mask) renderer->SetBackground(1.0, 0.0, 0.0);  // nothing visible: red, neither lit nor shadowed
    return {};
}

}  // namespace shadowlab
