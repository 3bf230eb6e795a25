#pragma once
// A QtTest suite's main: VTK's OpenGL surface format, an application, and QSettings kept in a
// temporary directory under the suite's own organization name, so that no run sees another's.
#include <QApplication>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

namespace shadowlab::testing {

template <class Suite>
int run_qt_suite(int argc, char** argv, const char* organization) {
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication app(argc, argv);
    QTemporaryDir settings;
    QApplication::setOrganizationName(organization);
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings.path());
    Suite suite;
    return QTest::qExec(&suite, argc, argv);
}

}  // namespace shadowlab::testing
