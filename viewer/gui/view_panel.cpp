#include "gui/view_panel.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QTimer>
#include <QVBoxLayout>
#include <glm/gtc/type_ptr.hpp>
#include <tuple>
#include <QVTKOpenGLNativeWidget.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkHandleWidget.h>
#include <vtkProperty.h>
#include <vtkSphereHandleRepresentation.h>
#include <vtkInteractorStyleImage.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include "scene/image_size.hpp"

namespace shadowlab {
namespace {

const char* preset_title(SpacePreset preset) {
    switch (preset) {
        case SpacePreset::orbit: return "Orbit";
        case SpacePreset::from_light: return "From the light";
        case SpacePreset::side: return "Side";
    }
    return "";
}

}  // namespace

ViewPanel::ViewPanel(const View& initial, QWidget* parent)
    : QWidget(parent),
      configuration_(new QLabel(this)),
      chooser_(new QComboBox(this)),
      error_(new QComboBox(this)),
      aliasing_(new QComboBox(this)),
      texture_(new QComboBox(this)),
      overlay_(new QComboBox(this)),
      preset_(new QComboBox(this)),
      scene_in_ppls_(new QCheckBox("Scene in PPLS", this)),
      widget_(new QVTKOpenGLNativeWidget(this)) {
    for (const View& v : all_views())
        chooser_->addItem(QString::fromStdString(v.title), QString::fromStdString(v.name));
    chooser_->setObjectName("viewChooser");
    for (const ErrorChoice& c : all_error_choices()) error_->addItem(c.title, static_cast<int>(c.shown));
    error_->setObjectName("errorChooser");
    error_->setToolTip(
        "each pixel's verdict (false shadow, false light, over Lloyd's m), its visibility error, "
        "method − reference (blue too dark, red too light), or each misclassified pixel's cause (acne, "
        "peter panning, under-sampling, ...: View ▸ Diagnosis ranks them); automatic: signed where "
        "shadows are soft (a light with a size, or a filter other than hard)");
    texture_->addItem("Depth", static_cast<int>(TextureShown::depth));
    texture_->addItem("Moments: mean", static_cast<int>(TextureShown::moment_mean));
    texture_->addItem("Moments: deviation", static_cast<int>(TextureShown::moment_deviation));
    texture_->setObjectName("textureChooser");
    texture_->setToolTip(
        "the stored depth, or what a vsm or evsm filter reads: its blurred moments' mean, or their "
        "standard deviation √(m₂ − m₁²), non-zero where the blur mixes depths");
    aliasing_->addItem("m", static_cast<int>(AliasingShown::total));
    aliasing_->addItem("m: perspective factor", static_cast<int>(AliasingShown::perspective));
    aliasing_->addItem("m: projection factor", static_cast<int>(AliasingShown::projection));
    aliasing_->setObjectName("aliasingChooser");
    aliasing_->setToolTip(
        "Lloyd's m, or its part a parameterization sets (perspective) or the surface's tilt sets "
        "(projection)");
    overlay_->addItem("Shadows", static_cast<int>(MapOverlay::none));
    overlay_->addItem("Map per pixel", static_cast<int>(MapOverlay::cascade_index));
    overlay_->addItem("Texels per pixel", static_cast<int>(MapOverlay::texels_per_pixel));
    overlay_->setObjectName("overlayChooser");
    overlay_->setToolTip(
        "the Camera view's colours: the shadows alone, or over them the map each pixel reads (a "
        "cascade's colour) or how many texels fall on a pixel (1/8 to 8)");
    for (SpacePreset p : all_space_presets()) preset_->addItem(preset_title(p), static_cast<int>(p));
    preset_->setObjectName("presetChooser");
    preset_->setToolTip(
        "a free perspective orbit; orthographic along the light (what the map sees); or orthographic "
        "from the side, in the plane of the light and the view direction (where a warp shows)");
    scene_in_ppls_->setObjectName("sceneInPpls");
    scene_in_ppls_->setChecked(ViewOptions{}.scene_in_ppls);
    scene_in_ppls_->setToolTip(
        "draw the scene's triangles in post-perspective light space (clipped near the unit cube)");
    connect(chooser_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &ViewPanel::show_choosers_for_view);
    set_view(initial);
    show_choosers_for_view();
    vtkNew<vtkGenericOpenGLRenderWindow> window;
    window_ = window;
    window_->SetStencilCapable(1);  // the stencil shadow pass (before the first render)
    widget_->setRenderWindow(window);
    widget_->setMinimumSize(200, 150);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    auto* choosers = new QHBoxLayout;
    configuration_->setObjectName("configuration");
    configuration_->setStyleSheet("font-weight: bold; padding: 0 6px");
    configuration_->hide();
    choosers->addWidget(configuration_);
    choosers->addWidget(chooser_, 1);
    choosers->addWidget(error_);
    choosers->addWidget(aliasing_);
    choosers->addWidget(texture_);
    choosers->addWidget(overlay_);
    choosers->addWidget(preset_);
    choosers->addWidget(scene_in_ppls_);
    layout->addLayout(choosers);
    layout->addWidget(widget_, 1);
    for (QComboBox* box : {chooser_, preset_})
        connect(box, QOverload<int>::of(&QComboBox::activated), this, [this] {
            forget_camera();  // another view or preset starts from its own camera
            emit viewChosen();
        });
    for (QComboBox* box : {error_, aliasing_, texture_, overlay_})
        connect(box, QOverload<int>::of(&QComboBox::activated), this, [this] { emit viewChosen(); });
    connect(scene_in_ppls_, &QCheckBox::toggled, this, [this] { emit viewChosen(); });

    vtkNew<vtkCallbackCommand> on_end;
    on_end->SetClientData(this);
    on_end->SetCallback(
        [](vtkObject*, unsigned long, void* self, void*) { static_cast<ViewPanel*>(self)->interaction_ended(); });
    window_->GetInteractor()->AddObserver(vtkCommand::EndInteractionEvent, on_end);
}

const View& ViewPanel::view() const { return view_or_throw(chooser_->currentData().toString().toStdString()); }

void ViewPanel::set_view(const View& view) {
    chooser_->setCurrentIndex(chooser_->findData(QString::fromStdString(view.name)));
    forget_camera();
}

SpacePreset ViewPanel::preset() const { return static_cast<SpacePreset>(preset_->currentData().toInt()); }

void ViewPanel::set_preset(SpacePreset preset) {
    preset_->setCurrentIndex(preset_->findData(static_cast<int>(preset)));
    forget_camera();
}

void ViewPanel::forget_camera() { kept_camera_.reset(); }

void ViewPanel::keep_camera(const CameraPose& pose) { kept_camera_ = pose; }

void ViewPanel::set_configuration(const QString& label) {
    configuration_->setText(label);
    configuration_->setVisible(!label.isEmpty());
}

QSize ViewPanel::drawing_size() const { return widget_->size(); }

void ViewPanel::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    emit resized();
}

// Each view shows the choosers it reads, however it was chosen.
void ViewPanel::show_choosers_for_view() {
    const ViewChoosers& shown = view().choosers;
    error_->setVisible(shown.error);
    aliasing_->setVisible(shown.aliasing);
    texture_->setVisible(shown.texture);
    overlay_->setVisible(shown.overlay);
    preset_->setVisible(shown.preset);
    scene_in_ppls_->setVisible(shown.scene_in_ppls);
}

ViewOptions ViewPanel::options_for(const ViewOptions& options, double aspect) const {
    ViewOptions sized = options;
    sized.width = std::max(64, widget_->width() / 2);  // the Error view traces half the panel's pixels
    sized.height = std::max(36, static_cast<int>(sized.width / aspect));
    sized.error = static_cast<ErrorShown>(error_->currentData().toInt());
    sized.aliasing = static_cast<AliasingShown>(aliasing_->currentData().toInt());
    sized.texture = static_cast<TextureShown>(texture_->currentData().toInt());
    sized.overlay = static_cast<MapOverlay>(overlay_->currentData().toInt());
    sized.preset = preset();
    sized.scene_in_ppls = scene_in_ppls_->isChecked();
    return sized;
}

ViewReport ViewPanel::show(const Inspection& inspection, const ViewOptions& options) {
    window_->GetRenderers()->RemoveAllItems();
    vtkNew<vtkRenderer> renderer;
    window_->AddRenderer(renderer);
    scene_renderer_ = renderer;
    camera_origin_ = inspection.scene.camera.position;  // the Camera view draws relative to it
    const View& shown = view();
    if (shown.interaction.through_scene_camera) letterbox(renderer, inspection.scene.camera);
    const ViewOptions sized = options_for(options, inspection.scene.camera.aspect);
    // A chooser the inspection gives nothing to choose is greyed: m beside the signed error, the
    // causes or a technique's verdicts, the moments of a filter that reads none.
    aliasing_->setEnabled(shows_aliasing(inspection, sized.error));
    texture_->setEnabled(inspection.has_map() && inspection.lookup.filter.reads_moments());
    const ViewReport report = build_view(renderer, inspection, shown, sized);
    const ViewDrag drag = shown.interaction.drag;
    if (kept_camera_ && drag == ViewDrag::orbits_kept) {
        kept_camera_->apply_to(renderer->GetActiveCamera());
        renderer->ResetCameraClippingRange();
    }
    if (drag == ViewDrag::pans_image)
        window_->GetInteractor()->SetInteractorStyle(vtkNew<vtkInteractorStyleImage>());
    else
        window_->GetInteractor()->SetInteractorStyle(vtkNew<vtkInteractorStyleTrackballCamera>());
    handles_.clear();
    if (shown.interaction.handles) add_world_handles(inspection);
    drawing_ = Drawing::render;
    return report;
}

// Two draggable handles (the World view's): the light (where its marker is drawn) and the camera,
// balls of a fixed size on screen whatever the scene's extent (a sphere handle's size is in pixels:
// VTK turns it into a world radius from the view's camera when it builds the ball).
void ViewPanel::add_world_handles(const Inspection& in) {
    constexpr double kHandlePixels = 16.0;  // the ball's bounding square's side: a radius of 16 / √2 px
    const Aabb bounds = in.scene.bounds();
    const glm::dvec3 centre = 0.5 * (bounds.min + bounds.max);
    const Light& light = in.scene.light;
    const glm::dvec3 light_at =
        light.is_directional() ? centre - 0.6 * bounds.diagonal() * light.direction : light.position;
    for (const auto& [at, colour, is_light] :
         {std::tuple{light_at, glm::dvec3(1.0, 0.85, 0.1), true},
          std::tuple{in.scene.camera.position, glm::dvec3(1.0, 1.0, 1.0), false}}) {
        vtkNew<vtkSphereHandleRepresentation> representation;
        representation->SetWorldPosition(const_cast<double*>(glm::value_ptr(at)));
        representation->SetHandleSize(kHandlePixels);
        representation->GetProperty()->SetColor(colour.r, colour.g, colour.b);
        auto handle = vtkSmartPointer<vtkHandleWidget>::New();
        handle->SetInteractor(window_->GetInteractor());
        handle->SetRepresentation(representation);
        handle->SetCurrentRenderer(scene_renderer_);
        handle->EnabledOn();
        vtkNew<vtkCallbackCommand> on_end;
        on_end->SetClientData(this);
        on_end->SetCallback(is_light ? [](vtkObject* caller, unsigned long, void* self, void*) {
            const double* p = static_cast<vtkHandleWidget*>(caller)->GetHandleRepresentation()->GetWorldPosition();
            emit static_cast<ViewPanel*>(self)->lightHandleMoved({p[0], p[1], p[2]});
        } : [](vtkObject* caller, unsigned long, void* self, void*) {
            const double* p = static_cast<vtkHandleWidget*>(caller)->GetHandleRepresentation()->GetWorldPosition();
            emit static_cast<ViewPanel*>(self)->cameraHandleMoved({p[0], p[1], p[2]});
        });
        handle->AddObserver(vtkCommand::EndInteractionEvent, on_end);
        handles_.push_back(handle);
    }
}

// The end of a drag: in a view that steers the scene's camera (the Camera view) it moves it; in
// one that keeps its orbit (a space view) the panel keeps the camera where the user left it.
void ViewPanel::interaction_ended() {
    if (!scene_renderer_) return;
    vtkCamera* c = scene_renderer_->GetActiveCamera();
    const ViewDrag drag = view().interaction.drag;
    if (drag == ViewDrag::orbits_kept) {
        kept_camera_ = CameraPose::of(c);
        emit orbitKept(*kept_camera_);
        return;
    }
    if (drag != ViewDrag::steers_scene_camera) return;
    const double* p = c->GetPosition();
    const double* f = c->GetFocalPoint();
    const double* u = c->GetViewUp();
    emit cameraMoved(camera_origin_ + glm::dvec3(p[0], p[1], p[2]), camera_origin_ + glm::dvec3(f[0], f[1], f[2]),
                     {u[0], u[1], u[2]});
}

// The Camera view keeps the aspect the inspection computed with (the scene's, locked: the matrices
// are the CLI's; or the panel's, unlocked): before each render its renderer takes the largest box
// of that shape in the panel, centred, over a dark backdrop on the layer below.
void ViewPanel::letterbox(vtkRenderer* renderer, const Camera& camera) {
    vtkNew<vtkRenderer> backdrop;
    backdrop->SetBackground(0.12, 0.13, 0.16);
    backdrop->InteractiveOff();
    window_->SetNumberOfLayers(2);
    window_->AddRenderer(backdrop);
    renderer->SetLayer(1);
    renderer->SetPreserveColorBuffer(0);  // it clears its own box
    renderer->SetPreserveDepthBuffer(0);
    vtkNew<vtkCallbackCommand> fit;
    fit->SetClientData(new Camera(camera));
    fit->SetClientDataDeleteCallback([](void* data) { delete static_cast<Camera*>(data); });
    fit->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
        auto* r = static_cast<vtkRenderer*>(caller);
        const int* size = r->GetRenderWindow()->GetSize();
        if (size[0] < 1 || size[1] < 1) return;
        const glm::ivec2 box = image_size_within(*static_cast<Camera*>(data), size[0], size[1]);
        const double x = 0.5 * (1.0 - double(box.x) / size[0]), y = 0.5 * (1.0 - double(box.y) / size[1]);
        r->SetViewport(x, y, 1.0 - x, 1.0 - y);
    });
    renderer->AddObserver(vtkCommand::StartEvent, fit);
}

// Rendered with the buffers left unswapped: VTK then keeps the image in its render framebuffer,
// and the widget does not ask Qt to compose the window with it (QVTKRenderWindowAdapter ignores
// such a frame). Presenting copies the image to the widget's framebuffer and asks for the
// composition (vtkOpenGLRenderWindow::Frame, with its WindowFrameEvent).
void ViewPanel::render() {
    if (drawing_ != Drawing::render) return;
    window_->SwapBuffersOff();
    window_->Render();
    window_->SwapBuffersOn();
    drawing_ = Drawing::present;
}

void ViewPanel::present() {
    if (drawing_ != Drawing::present) return;
    window_->MakeCurrent();
    window_->Frame();
    drawing_ = Drawing::done;
}

RgbImage ViewPanel::grab() {
    render();
    present();
    const QImage frame = widget_->grabFramebuffer().convertToFormat(QImage::Format_RGB888);
    RgbImage image(frame.width(), frame.height());
    for (int y = 0; y < frame.height(); ++y)
        std::copy_n(frame.constScanLine(y), static_cast<size_t>(frame.width()) * 3, image.at(0, y));
    return image;
}

}  // namespace shadowlab
