#include "gui/inspector_app.hpp"

#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>

#include "gui/controls_panel.hpp"
#include "gui/main_window.hpp"
#include "render/x_display.hpp"

namespace shadowlab {

int run_inspector(int argc, char** argv, const InspectorOptions& options) {
    { const XDisplay probe("windows"); }  // a clear message instead of Qt's abort
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication::setOrganizationName("ShadowLab");
    QApplication::setApplicationName("shadowlab");
    QApplication app(argc, argv);
    MainWindow window;
    window.resize(options.width, options.height);
    window.show();
    QApplication::processEvents();  // lay out first: the panels draw at their size
    window.open_file(QString::fromStdString(options.scene_file));
    if (options.compare.size() == 2) {
        window.controls()->set_method(QString::fromStdString(options.compare[0]));
        window.set_compare_mode(true);
        window.compared_controls()->set_method(QString::fromStdString(options.compare[1]));
    }
    QTimer settled;  // the screenshot once the scene is computed and every panel drawn
    if (!options.screenshot.empty()) {
        settled.setInterval(100);
        QObject::connect(&settled, &QTimer::timeout, &window, [&] {
            if (window.computing()) return;
            const bool ok = window.grab().save(QString::fromStdString(options.screenshot));
            QApplication::exit(ok ? 0 : 1);
        });
        settled.start();
    }
    return QApplication::exec();
}

}  // namespace shadowlab
