#include "render/x_display.hpp"

#include <chrono>
#include <stdexcept>
#include <thread>

#include <X11/Xlib.h>

namespace shadowlab {

XDisplay::XDisplay(const std::string& purpose) {
    for (int attempt = 0; attempt < 5 && !display_; ++attempt) {
        if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(100 * attempt));
        display_ = XOpenDisplay(nullptr);
    }
    if (!display_) throw std::runtime_error(purpose + " need an X display: run under xvfb-run");
}

XDisplay::~XDisplay() { XCloseDisplay(static_cast<Display*>(display_)); }

}  // namespace shadowlab
