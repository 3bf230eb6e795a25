// What the views share: the actors, the scene camera placed, images shown crisp, the heat ramp, maps named.
#include "views/view_parts.hpp"

#include <algorithm>
#include <array>

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

#include "maps/projection_kind.hpp"

namespace shadowlab {

std::string map_name(const ShadowSetup& setup, size_t i) {
    static const char* const kFaces[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    switch (setup.selection.rule) {
        case MapSelection::Rule::view_depth: return "cascade " + std::to_string(i + 1);
        case MapSelection::Rule::hemisphere: return i == 0 ? "front" : "back";
        case MapSelection::Rule::face_axis:  // a cube's faces by their axes, others by their index
            return projection_kind(setup.maps[i]).numbered_face
                       ? std::string("face ") + kFaces[setup.maps[i].cube_face % 6]
                       : "face " + std::to_string(i);
        case MapSelection::Rule::pages: {
            const PageAddress& a = setup.selection.pages.pages[i];
            return "level " + std::to_string(a.level) + " page " + std::to_string(a.page.x) + "," +
                   std::to_string(a.page.y);
        }
        default: return "map " + std::to_string(i + 1);
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

void fill_block(RgbImage& image, size_t i, const Rgb& colour) {
    const int x = static_cast<int>(i % image.width), y = static_cast<int>(i / image.width);
    for (int ny = std::max(0, y - 1); ny <= std::min(image.height - 1, y + 1); ++ny)
        for (int nx = std::max(0, x - 1); nx <= std::min(image.width - 1, x + 1); ++nx)
            std::copy(colour.begin(), colour.end(), image.at(nx, ny));
}

}  // namespace shadowlab
