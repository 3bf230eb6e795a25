#pragma once
// The panels' redraws, queued (issue 16): building a panel's view, rendering it and presenting it
// are each one turn of the event loop, one panel after another, so that the GUI thread answers
// between them (each takes tens of milliseconds for a town under a software OpenGL). A panel still
// queued when a newer inspection lands is built from that one. (Presenting each panel before the
// next is rendered, rather than all together, lets a software rasterizer finish one panel before it
// starts the next.)
#include <functional>
#include <vector>
#include <QObject>

namespace shadowlab {

class ViewPanel;

class PanelScheduler : public QObject {
public:
    // `build` builds a panel's view from the inspection shown (ViewPanel::show), or leaves it
    // with nothing to draw.
    PanelScheduler(std::function<void(ViewPanel*)> build, QObject* parent);

    void redraw(ViewPanel* panel);
    bool busy() const { return !undrawn_.empty(); }  // a panel is still to build, render or present
    // How many turns of the event loop have drawn with OpenGL so far (a panel rendered, or presented).
    int drawings() const { return drawings_; }

private:
    void draw_next();

    std::function<void(ViewPanel*)> build_;
    std::vector<ViewPanel*> undrawn_;  // the panels still to build, render and present, the front first
    int drawings_ = 0;
};

}  // namespace shadowlab
