#include "views/offscreen_view.hpp"

#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "render/x_display.hpp"

namespace shadowlab {

void with_offscreen_view(const Inspection& inspection, const View& view, const ViewOptions& options, int width,
                         int height, const UseBuiltView& use) {
    const XDisplay x("views");  // before VTK would open one
    vtkNew<vtkRenderWindow> window;
    // No interactor: initializing one syncs with an X window an offscreen render never maps.
    window->SetInteractor(nullptr);
    window->SetDisplayId(x.handle());
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);    // pixel tests compare exact colours
    window->SetStencilCapable(1);  // the stencil shadow pass (before the first render)
    window->SetSize(width, height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    ViewOptions sized = options;
    if (sized.width <= 0) sized.width = width, sized.height = height;
    const ViewReport report = build_view(renderer, inspection, view, sized);
    use(window, renderer, report);
    window->Finalize();
}

RgbImage render_view(const Inspection& inspection, const View& view, const ViewOptions& options, int width,
                     int height) {
    RgbImage image;
    with_offscreen_view(inspection, view, options, width, height,
                        [&](vtkRenderWindow* window, vtkRenderer*, const ViewReport&) {
                            window->Render();
                            image = grab(window);
                        });
    return image;
}

}  // namespace shadowlab
