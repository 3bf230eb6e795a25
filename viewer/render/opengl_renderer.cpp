#include "render/opengl_renderer.hpp"

#include <sstream>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include "render/x_display.hpp"

namespace shadowlab {
namespace {

std::string probe_renderer() {
    const XDisplay x("an OpenGL probe");
    vtkNew<vtkRenderWindow> window;
    window->SetInteractor(nullptr);
    window->SetDisplayId(x.handle());
    window->SetOffScreenRendering(1);
    window->SetSize(1, 1);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    window->Render();
    std::istringstream capabilities(window->ReportCapabilities());
    std::string line, found;
    const std::string key = "OpenGL renderer string:";
    while (std::getline(capabilities, line))
        if (line.rfind(key, 0) == 0) found = line.substr(line.find_first_not_of(' ', key.size()));
    window->Finalize();
    return found;
}

}  // namespace

const std::string& opengl_renderer() {
    static const std::string renderer = [] {
        try {
            return probe_renderer();
        } catch (const std::exception&) {
            return std::string();
        }
    }();
    return renderer;
}

bool is_software_renderer(const std::string& renderer) {
    for (const char* software : {"llvmpipe", "softpipe", "swrast"})
        if (renderer.find(software) != std::string::npos) return true;
    return false;
}

}  // namespace shadowlab
