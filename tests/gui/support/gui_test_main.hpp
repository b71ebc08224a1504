// The main() of a QTest executable whose widgets may hold a VTK view: QVTKOpenGLNativeWidget needs
// its OpenGL surface format set before the QApplication exists, so QTEST_MAIN cannot be used.
// Where VTK is not on the include path (a studio built without VTK pages) only the application
// and the test run.
#pragma once

#include <QApplication>
#include <QSurfaceFormat>
#include <QTest>

#if __has_include(<QVTKOpenGLNativeWidget.h>)
#include <QVTKOpenGLNativeWidget.h>
#define CLM3D_GUI_TEST_SET_VTK_FORMAT() \
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat())
#else
#define CLM3D_GUI_TEST_SET_VTK_FORMAT() \
  do {                                  \
  } while (false)
#endif

// Defines main() running the QTest object of class TestClass.
#define CLM3D_GUI_TEST_MAIN(TestClass)      \
  int main(int argc, char** argv) {         \
    CLM3D_GUI_TEST_SET_VTK_FORMAT();        \
    QApplication app(argc, argv);           \
    TestClass test;                         \
    return QTest::qExec(&test, argc, argv); \
  }
