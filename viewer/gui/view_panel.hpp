#pragma once
// One view of the window: a chooser for which view it shows (and, for the Error view, which
// aliasing its heat map paints), over a VTK widget drawing it.
#include <optional>
#include <vector>
#include <QWidget>
#include <vtkSmartPointer.h>

#include "render/rgb_image.hpp"
#include "views/view.hpp"

class QComboBox;
class QVTKOpenGLNativeWidget;
class vtkGenericOpenGLRenderWindow;
class vtkHandleWidget;
class vtkRenderer;

namespace shadowlab {

class ViewPanel : public QWidget {
    Q_OBJECT
public:
    ViewPanel(ViewKind initial, QWidget* parent = nullptr);

    ViewKind view() const;
    void set_view(ViewKind view);
    // Redraws from the inspection; returns what the view could not draw.
    ViewReport show(const Inspection& inspection, const ViewOptions& options);
    RgbImage grab();  // what the panel shows now

signals:
    void viewChosen();
    // The user moved the camera in the Camera view: its new position, target and up.
    void cameraMoved(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up);
    // The user dragged a handle in the World view: the light's (the world point it now sits at)
    // or the camera's (its new position; the target stays).
    void lightHandleMoved(const glm::dvec3& point);
    void cameraHandleMoved(const glm::dvec3& position);

private:
    void report_camera();
    void add_world_handles(const Inspection& inspection);
    void letterbox(vtkRenderer* renderer, const Camera& camera);

    std::vector<vtkSmartPointer<vtkHandleWidget>> handles_;
    QComboBox* chooser_;
    QComboBox* aliasing_;  // the Error view's heat map: m or one of its factors
    QVTKOpenGLNativeWidget* widget_;
    vtkGenericOpenGLRenderWindow* window_;
    vtkRenderer* scene_renderer_ = nullptr;  // the view's own, the first of the window's renderers
    glm::dvec3 camera_origin_{0.0};          // the Camera view's coordinates are relative to it
};

}  // namespace shadowlab
