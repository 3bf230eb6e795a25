#pragma once
// The window computes off the GUI thread: a test waits for the newest change's inspection to land
// (the views then drawn from it) before it looks.
#include <QApplication>
#include <QtTest>

#include "gui/main_window.hpp"

namespace shadowlab::testing {

// A change may reach the window a turn of the event loop after it was made (a chooser's signal, a
// resize): the events are processed first, and again until no computation is started by them.
inline bool settled(const MainWindow& window) {
    do {
        QApplication::processEvents();
        if (!QTest::qWaitFor([&] { return !window.computing(); }, 120000)) return false;
        QApplication::processEvents();
    } while (window.computing());
    return true;
}

}  // namespace shadowlab::testing
