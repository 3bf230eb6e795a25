// The Camera view: the scene as the camera sees it, shadowed by the method's own map on the GPU.
#include <vtkActor.h>
#include <vtkLight.h>
#include <vtkProperty.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>

#include "render/shadow_map_pass.hpp"
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

}  // namespace

ViewReport build_camera_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options) {
    const std::vector<glm::dvec3> colours = options.lit_mask ? std::vector<glm::dvec3>(in.scene.objects.size(), glm::dvec3(1.0))
                                                             : object_colours(in.scene);
    std::vector<bool> not_casting(in.casters.size());
    for (size_t i = 0; i < in.casters.size(); ++i) not_casting[i] = !in.casters[i];
    auto casters = actor_for(triangles_polydata(in.triangles, in.casters, colours, glm::dmat4(1.0)), glm::dvec3(1.0));
    auto others = actor_for(triangles_polydata(in.triangles, not_casting, colours, glm::dmat4(1.0)), glm::dvec3(1.0));
    for (vtkActor* actor : {casters.Get(), others.Get()}) {
        actor->GetProperty()->SetAmbient(0.35);
        actor->GetProperty()->SetDiffuse(0.75);
        actor->GetProperty()->BackfaceCullingOff();
        renderer->AddActor(actor);
    }
    add_scene_light(renderer, in.scene.light);
    place_scene_camera(renderer, in.scene.camera);
    renderer->SetBackground(0.62, 0.74, 0.86);

    vtkNew<ShadowMapPass> pass;
    pass->SetMap(in.map().world_to_uvz, in.map().z_bias_scale, in.resolution);
    const Light& light = in.scene.light;
    pass->SetBias(in.bias, light.is_directional() ? glm::dvec4(light.direction, 0.0) : glm::dvec4(light.position, 1.0),
                  in.scene.camera.position);
    pass->SetCasters({casters.Get()});
    pass->SetShadePass(vtkNew<vtkRenderStepsPass>());
    pass->SetOutput(options.lit_mask ? ShadowMapPass::Output::lit_mask : ShadowMapPass::Output::shaded);
    renderer->SetPass(pass);
    if (options.lit_mask) renderer->SetBackground(1.0, 0.0, 0.0);  // nothing visible: red, neither lit nor shadowed
    return {};
}

}  // namespace shadowlab
