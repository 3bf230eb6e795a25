// What drawing one panel of the window costs on its GUI thread after a change, on the default scene
// (focused, 1024², the window's defaults), for the four views the window opens with: building the
// view's VTK actors from the inspection, and rendering them the first time (a change brings new
// actors: their buffers are uploaded, the shadow map pass renders its depth texture). Offscreen, at
// a panel's size in a 1280×800 window; needs an X display (xvfb-run), under which OpenGL is Mesa's
// llvmpipe, which rasterizes on the CPU as the window does here.
#include <benchmark/benchmark.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include "model/inspection.hpp"
#include "render/x_display.hpp"
#include "scene/scene_loader.hpp"
#include "views/view.hpp"

using namespace shadowlab;

namespace {

constexpr int kPanelWidth = 320, kPanelHeight = 400;

const Inspection& default_inspection() {
    static const Inspection inspection = [] {
        const Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json");
        Inspection in = inspect_scene(scene, InspectionRequest{});
        for (const View& view : all_views()) prepare_view(in, view, ViewOptions{});
        return in;
    }();
    return inspection;
}

// An offscreen window of a panel's size, as the window's panels are configured (no multisampling
// under a software OpenGL, a stencil buffer for the volumes pass).
struct PanelWindow {
    XDisplay x{"the drawing benchmarks"};
    vtkNew<vtkRenderWindow> window;
    PanelWindow() {
        window->SetInteractor(nullptr);
        window->SetDisplayId(x.handle());
        window->SetOffScreenRendering(1);
        window->SetMultiSamples(0);
        window->SetStencilCapable(1);
        window->SetSize(kPanelWidth, kPanelHeight);
    }
    ~PanelWindow() { window->Finalize(); }
};

ViewOptions panel_options() {
    ViewOptions options;
    options.width = kPanelWidth / 2;  // as ViewPanel::options_for sizes them
    options.height = kPanelHeight / 2;
    return options;
}

void build(benchmark::State& state, const View* view) {
    const Inspection& in = default_inspection();
    for (auto _ : state) {
        vtkNew<vtkRenderer> renderer;
        benchmark::DoNotOptimize(build_view(renderer, in, *view, panel_options()));
    }
}

// Each iteration a new renderer with new actors, as after a change; only the render is timed.
void first_render(benchmark::State& state, const View* view) {
    const Inspection& in = default_inspection();
    PanelWindow panel;
    for (auto _ : state) {
        state.PauseTiming();
        panel.window->GetRenderers()->RemoveAllItems();
        vtkNew<vtkRenderer> renderer;
        panel.window->AddRenderer(renderer);
        build_view(renderer, in, *view, panel_options());
        state.ResumeTiming();
        panel.window->Render();
    }
}

// The same actors rendered again, as while the user orbits a view.
void render_again(benchmark::State& state, const View* view) {
    const Inspection& in = default_inspection();
    PanelWindow panel;
    vtkNew<vtkRenderer> renderer;
    panel.window->AddRenderer(renderer);
    build_view(renderer, in, *view, panel_options());
    panel.window->Render();
    for (auto _ : state) panel.window->Render();
}

const bool kRegistered = [] {
    for (const char* shown : {"world", "camera", "light", "shadowmap"}) {
        const View* view = &view_or_throw(shown);
        const std::string& name = view->title;
        benchmark::RegisterBenchmark(("view_build/" + name).c_str(), build, view)->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("view_first_render/" + name).c_str(), first_render, view)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("view_render_again/" + name).c_str(), render_again, view)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
    return true;
}();

}  // namespace
