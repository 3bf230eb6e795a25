#pragma once
// The X display VTK renders on, opened by us (with a few retries: a busy Xvfb refuses a connection
// now and then) and handed to VTK, which would abort the process on a failed open of its own.
#include <string>

namespace shadowlab {

class XDisplay {
public:
    // Throws std::runtime_error("<purpose> need an X display: run under xvfb-run") when none opens.
    explicit XDisplay(const std::string& purpose);
    ~XDisplay();
    XDisplay(const XDisplay&) = delete;
    XDisplay& operator=(const XDisplay&) = delete;

    void* handle() const { return display_; }  // a Display*, for vtkRenderWindow::SetDisplayId

private:
    void* display_ = nullptr;
};

}  // namespace shadowlab
