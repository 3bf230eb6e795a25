#pragma once
// One view of the window: a chooser for which view it shows, and beside it the choosers the view's
// descriptor names (ViewChoosers: for the Error view, verdicts or the signed visibility error, and
// which aliasing its heat map paints; for the Shadow map view, the depth or the moments a vsm or
// evsm filter reads; for World, Light space and PPLS, how the camera looks at it; for PPLS, whether
// the scene is drawn), over a VTK widget drawing it. A drag does what the descriptor says
// (ViewDrag): an orbit the user leaves in a view that keeps it is kept across redraws until the
// view or its preset changes.
#include <optional>
#include <vector>
#include <QWidget>
#include <vtkSmartPointer.h>

#include "gui/camera_pose.hpp"
#include "render/rgb_image.hpp"
#include "views/view.hpp"

class QCheckBox;
class QComboBox;
class QLabel;
class QVTKOpenGLNativeWidget;
class vtkGenericOpenGLRenderWindow;
class vtkHandleWidget;
class vtkRenderer;

namespace shadowlab {

class ViewPanel : public QWidget {
    Q_OBJECT
public:
    ViewPanel(const View& initial, QWidget* parent = nullptr);

    const View& view() const;
    void set_view(const View& view);
    SpacePreset preset() const;
    void set_preset(SpacePreset preset);
    void forget_camera();  // the next redraw places the view's default camera (a new scene)
    // The next redraws place this orbit, as if the user had left it (a view that keeps its orbit):
    // the window's compare mode moves one panel's camera with the other's.
    void keep_camera(const CameraPose& pose);
    // Which configuration of compare mode the panel draws ("A", "B"), shown before its chooser; empty: none.
    void set_configuration(const QString& label);
    QSize drawing_size() const;  // the VTK widget's, without the choosers
    // `options` completed by the panel's choosers and size, for a camera of `aspect`: what show draws with.
    ViewOptions options_for(const ViewOptions& options, double aspect) const;
    // Builds the view from the inspection, to be rendered; returns what the view could not draw.
    ViewReport show(const Inspection& inspection, const ViewOptions& options);
    // Renders the view built last into the panel's framebuffer, not yet on screen. Building,
    // rendering and presenting each take a turn of the window's event loop (under a software OpenGL
    // tens of milliseconds each: presenting waits for the rasterizer, and Qt composes the window),
    // and the GUI thread answers between them.
    void render();
    void present();  // what render() drew, on screen
    bool rendering_pending() const { return drawing_ == Drawing::render; }
    bool presenting_pending() const { return drawing_ == Drawing::present; }
    void drop_drawing() { drawing_ = Drawing::done; }  // what show() built is neither rendered nor presented
    RgbImage grab();  // what the panel shows now (rendered and presented first if pending)

signals:
    void viewChosen();
    // The user moved the camera in a view that steers it (the Camera view): its new position, target and up.
    void cameraMoved(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up);
    // The user dragged a handle (ViewInteraction::handles, the World view's): the light's (the world point it now sits
    // at) or the camera's (its new position; the target stays).
    void lightHandleMoved(const glm::dvec3& point);
    void cameraHandleMoved(const glm::dvec3& position);
    void resized();  // the Camera view's aspect may follow the panel's shape
    // The user left an orbit in a view that keeps it (ViewDrag::orbits_kept).
    void orbitKept(const CameraPose& pose);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void show_choosers_for_view();
    void interaction_ended();
    void add_world_handles(const Inspection& inspection);
    void letterbox(vtkRenderer* renderer, const Camera& camera);

    std::vector<vtkSmartPointer<vtkHandleWidget>> handles_;
    QLabel* configuration_;  // compare mode's A or B
    QComboBox* chooser_;
    QComboBox* error_;     // the Error view: automatic, verdicts or the signed visibility error
    QComboBox* aliasing_;  // the Error view's heat map: m or one of its factors (verdicts only)
    QComboBox* texture_;   // the Shadow map view: depth, or the moments' mean or deviation (vsm, evsm)
    QComboBox* overlay_;   // the Camera view: shadows alone, or the map per pixel, or texels per pixel
    QComboBox* preset_;    // World, Light space, PPLS: orbit, from the light, side
    QCheckBox* scene_in_ppls_;
    std::optional<CameraPose> kept_camera_;  // the user's, in a view that keeps its orbit
    QVTKOpenGLNativeWidget* widget_;
    vtkGenericOpenGLRenderWindow* window_;
    vtkRenderer* scene_renderer_ = nullptr;  // the view's own, the first of the window's renderers
    enum class Drawing { done, render, present };
    Drawing drawing_ = Drawing::done;
    glm::dvec3 camera_origin_{0.0};  // the Camera view's coordinates are relative to it
};

}  // namespace shadowlab
