#include "gui/panel_scheduler.hpp"

#include <QTimer>
#include <algorithm>
#include <utility>

#include "gui/view_panel.hpp"

namespace shadowlab {

PanelScheduler::PanelScheduler(std::function<void(ViewPanel*)> build, QObject* parent)
    : QObject(parent), build_(std::move(build)) {}

void PanelScheduler::redraw(ViewPanel* panel) {
    const bool idle = undrawn_.empty();
    // Only the front can be built already, from an older inspection: its drawing is dropped, to be
    // built again rather than rendered and shown stale.
    if (!idle && undrawn_.front() == panel) panel->drop_drawing();
    if (std::find(undrawn_.begin(), undrawn_.end(), panel) == undrawn_.end()) undrawn_.push_back(panel);
    if (idle) QTimer::singleShot(1, this, &PanelScheduler::draw_next);
}

// One turn: the front panel presented, or rendered, or built.
void PanelScheduler::draw_next() {
    if (undrawn_.empty()) return;
    ViewPanel* panel = undrawn_.front();
    if (panel->presenting_pending()) {
        panel->present();
        ++drawings_;
        undrawn_.erase(undrawn_.begin());
    } else if (panel->rendering_pending()) {
        panel->render();
        ++drawings_;
    } else {
        build_(panel);
        if (!panel->rendering_pending()) undrawn_.erase(undrawn_.begin());  // nothing to draw
    }
    if (!undrawn_.empty()) QTimer::singleShot(1, this, &PanelScheduler::draw_next);
}

}  // namespace shadowlab
