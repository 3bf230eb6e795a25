#include "views/view.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageMapper3D.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkCellData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "views/space_parts.hpp"
#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

struct ViewName {
    ViewKind view;
    const char* name;
    const char* title;
};

constexpr std::array<ViewName, 8> kViews{{{ViewKind::camera, "camera", "Camera"},
                                          {ViewKind::world, "world", "World"},
                                          {ViewKind::light, "light", "Light space"},
                                          {ViewKind::ppls, "ppls", "PPLS"},
                                          {ViewKind::shadow_map, "shadowmap", "Shadow map"},
                                          {ViewKind::texels, "texels", "Texels"},
                                          {ViewKind::error, "error", "Error"},
                                          {ViewKind::stencil, "stencil", "Stencil count"}}};

const ViewName& entry(ViewKind view) {
    for (const ViewName& v : kViews)
        if (v.view == view) return v;
    throw std::logic_error("unnamed view");
}

}  // namespace

const char* to_string(ViewKind view) { return entry(view).name; }
const char* view_title(ViewKind view) { return entry(view).title; }

std::optional<ViewKind> view_named(const std::string& name) {
    for (const ViewName& v : kViews)
        if (name == v.name) return v.view;
    return std::nullopt;
}

const std::vector<ViewKind>& all_views() {
    static const std::vector<ViewKind> views = [] {
        std::vector<ViewKind> out;
        for (const ViewName& v : kViews) out.push_back(v.view);
        return out;
    }();
    return views;
}

const char* to_string(SpacePreset preset) {
    switch (preset) {
        case SpacePreset::orbit: return "orbit";
        case SpacePreset::from_light: return "light";
        case SpacePreset::side: return "side";
    }
    return "?";
}

const std::vector<SpacePreset>& all_space_presets() {
    static const std::vector<SpacePreset> presets{SpacePreset::orbit, SpacePreset::from_light, SpacePreset::side};
    return presets;
}

std::optional<SpacePreset> space_preset_named(const std::string& name) {
    for (SpacePreset p : all_space_presets())
        if (name == to_string(p)) return p;
    return std::nullopt;
}

std::string map_name(const ShadowSetup& setup, size_t i) {
    static const char* const kFaces[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    switch (setup.selection.rule) {
        case MapSelection::Rule::view_depth: return "cascade " + std::to_string(i + 1);
        case MapSelection::Rule::hemisphere: return i == 0 ? "front" : "back";
        case MapSelection::Rule::cube_face: return std::string("face ") + kFaces[setup.maps[i].cube_face % 6];
        default: return "map " + std::to_string(i + 1);
    }
}

bool soft_shadows(const Inspection& in) {
    return in.scene.light.is_area() || (in.has_map() && in.lookup.filter.soft());
}

bool shows_signed_error(const Inspection& in, ErrorShown shown) {
    return shown == ErrorShown::automatic ? soft_shadows(in) : shown == ErrorShown::signed_visibility;
}

bool looks_through_scene_camera(ViewKind view) { return view == ViewKind::camera || view == ViewKind::texels; }

bool shows_steps(ViewKind view) { return view == ViewKind::world || view == ViewKind::light || view == ViewKind::ppls; }

ViewReport build_view(vtkRenderer* renderer, const Inspection& in, ViewKind view, const ViewOptions& options) {
    if (!options.step.empty() && !in.trace.find(options.step))
        throw std::invalid_argument("method " + in.name() + " has no step '" + options.step + "'");
    switch (view) {
        case ViewKind::camera: return build_camera_view(renderer, in, options);
        case ViewKind::shadow_map: return build_shadow_map_view(renderer, in, options);
        case ViewKind::texels: return build_texels_view(renderer, in);
        case ViewKind::error: return build_error_view(renderer, in, options);
        case ViewKind::stencil: return build_stencil_view(renderer, in);
        default: return build_space_view(renderer, in, view, options);
    }
}

void prepare_view(const Inspection& in, ViewKind view, const ViewOptions& options) {
    switch (view) {
        case ViewKind::camera: return;  // drawn on the GPU
        case ViewKind::shadow_map:
            if (in.has_map()) in.depth();
            return;
        case ViewKind::texels:
            if (in.has_map()) in.surface_depth();
            return;
        case ViewKind::error: {
            const glm::ivec2 size = judged_image_size(in, options);
            in.error(size.x, size.y);
            return;
        }
        case ViewKind::stencil: return;  // a technique's own image, traced when it ran
        default:
            if (in.has_map()) visible_points_missed(in);  // the space views mark them
    }
}

vtkSmartPointer<vtkActor> actor_for(const Placed& placed, const glm::dvec3& colour) {
    auto mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
    mapper->SetInputData(placed.data);
    // World coordinates straight to the shaders: the shadow pass reads vertexMC as a world point.
    mapper->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
    mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray("colour");
    mapper->SetColorModeToDirectScalars();
    mapper->SetScalarVisibility(placed.data->GetCellData()->GetArray("colour") != nullptr);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colour.r, colour.g, colour.b);
    return actor;
}

void place_scene_camera(vtkRenderer* renderer, const Camera& camera) {
    vtkCamera* vtk = renderer->GetActiveCamera();
    vtk->SetPosition(camera.position.x, camera.position.y, camera.position.z);
    vtk->SetFocalPoint(camera.target.x, camera.target.y, camera.target.z);
    vtk->SetViewUp(camera.up.x, camera.up.y, camera.up.z);
    vtk->SetViewAngle(camera.fov_y_deg);
    vtk->SetParallelProjection(camera.is_orthographic());
    vtk->SetParallelScale(camera.half_height);  // VTK's parallel scale is half the view's height
    vtk->SetClippingRange(camera.near, camera.far);
}

void show_image(vtkRenderer* renderer, const RgbImage& image) {
    const int width = image.width, height = image.height;
    vtkNew<vtkImageActor> actor;
    actor->GetMapper()->SetInputData(to_vtk_image(image));
    actor->InterpolateOff();  // texels stay crisp squares when zoomed in
    renderer->AddActor(actor);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetPosition((width - 1) / 2.0, (height - 1) / 2.0, 10.0 * std::max(width, height));
    camera->SetFocalPoint((width - 1) / 2.0, (height - 1) / 2.0, 0.0);
    camera->SetViewUp(0, 1, 0);
    // Fit the whole image: by its height, or by its width in a window narrower than the image.
    double window_aspect = static_cast<double>(width) / height;
    if (const int* size = renderer->GetRenderWindow() ? renderer->GetRenderWindow()->GetSize() : nullptr;
        size && size[0] > 0 && size[1] > 0)
        window_aspect = static_cast<double>(size[0]) / size[1];
    camera->SetParallelScale(std::max(height / 2.0, width / (2.0 * window_aspect)));
    renderer->ResetCameraClippingRange();
}

Rgb heat(double t) {
    static constexpr std::array<std::array<double, 3>, 5> stops{
        {{0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}}};
    t = std::clamp(t, 0.0, 1.0) * (stops.size() - 1);
    const size_t i = std::min(static_cast<size_t>(t), stops.size() - 2);
    const double f = t - i;
    Rgb out{};
    for (int c = 0; c < 3; ++c) out[c] = static_cast<unsigned char>(stops[i][c] + f * (stops[i + 1][c] - stops[i][c]));
    return out;
}

}  // namespace shadowlab
