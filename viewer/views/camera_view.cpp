// The Camera view: the scene as the camera sees it, shadowed on the GPU: by the method's own map
// (ShadowMapPass), or for a geometric technique by its polygons in the stencil buffer
// (StencilVolumePass): the shadow volume for `volumes`, and for `planar` the flattened casters
// drawn onto their plane (Blinn's projection shadows, the stencil keeping overlaps from darkening twice).
#include <vtkActor.h>
#include <vtkLight.h>
#include <vtkProperty.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>

#include "render/shadow_map_pass.hpp"
#include "render/stencil_volume_pass.hpp"
#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

// The scene's light as a VTK light, so that diffuse shading agrees with the shadows.
void add_scene_light(vtkRenderer* renderer, const Light& light) {
    renderer->AutomaticLightCreationOff();
    renderer->RemoveAllLights();
    vtkNew<vtkLight> vtk;
    vtk->SetLightTypeToSceneLight();
    if (light.is_directional()) {
        vtk->SetPositional(false);
        vtk->SetPosition(-light.direction.x, -light.direction.y, -light.direction.z);
        vtk->SetFocalPoint(0.0, 0.0, 0.0);
    } else {
        vtk->SetPositional(true);
        vtk->SetConeAngle(90.0);  // a point light: the map decides what is lit
        vtk->SetPosition(light.position.x, light.position.y, light.position.z);
        const glm::dvec3 aim = light.position + (light.type == LightType::spot ? light.direction : glm::dvec3(0, -1, 0));
        vtk->SetFocalPoint(aim.x, aim.y, aim.z);
    }
    renderer->AddLight(vtk);
}

void install_map_pass(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options, vtkActor* casters,
                      const Light& light) {
    vtkNew<ShadowMapPass> pass;
    pass->SetSetup(relative_to(in.setup, in.scene.camera.position), in.resolution);
    pass->SetBias(in.bias, light.is_directional() ? glm::dvec4(light.direction, 0.0) : glm::dvec4(light.position, 1.0),
                  glm::dvec3(0.0));  // the eye
    pass->SetCasters({casters});
    pass->SetShadePass(vtkNew<vtkRenderStepsPass>());
    pass->SetOutput(options.lit_mask ? ShadowMapPass::Output::lit_mask : ShadowMapPass::Output::shaded);
    renderer->SetPass(pass);
}

void install_stencil_pass(vtkRenderer* renderer, const GeometryResult& technique, const ViewOptions& options,
                          const glm::dvec3& origin) {
    vtkNew<StencilVolumePass> pass;
    std::vector<HomogeneousPolygon> local;
    for (const HomogeneousPolygon& p : technique.stencil) local.push_back(translated(p, -origin));
    pass->SetPolygons(local, technique.rule);
    pass->SetScenePass(vtkNew<vtkRenderStepsPass>());
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
    const std::vector<glm::dvec3> colours = options.lit_mask ? std::vector<glm::dvec3>(in.scene.objects.size(), glm::dvec3(1.0))
                                                             : object_colours(in.scene);
    std::vector<bool> not_casting(in.casters.size());
    for (size_t i = 0; i < in.casters.size(); ++i) not_casting[i] = !in.casters[i];
    auto casters = actor_for(triangles_polydata(in.triangles, in.casters, colours, local_from_world), glm::dvec3(1.0));
    auto others = actor_for(triangles_polydata(in.triangles, not_casting, colours, local_from_world), glm::dvec3(1.0));
    // A lit mask from the stencil pass: the scene flat white, blackened where the stencil is set.
    const bool flat = options.lit_mask && !in.has_map();
    for (vtkActor* actor : {casters.Get(), others.Get()}) {
        actor->GetProperty()->SetAmbient(flat ? 1.0 : 0.35);
        actor->GetProperty()->SetDiffuse(flat ? 0.0 : 0.75);
        actor->GetProperty()->BackfaceCullingOff();
        renderer->AddActor(actor);
    }
    add_scene_light(renderer, light);
    place_scene_camera(renderer, camera);
    renderer->SetBackground(0.62, 0.74, 0.86);
    if (in.has_map())
        install_map_pass(renderer, in, options, casters, light);
    else
        install_stencil_pass(renderer, *in.geometry, options, origin);
    if (options.lit_mask) renderer->SetBackground(1.0, 0.0, 0.0);  // nothing visible: red, neither lit nor shadowed
    return {};
}

}  // namespace shadowlab
