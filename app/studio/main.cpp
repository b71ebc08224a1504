// clm3d-studio: the GUI. Everything but Qt/VTK set-up is in ui/shell (studio_launch.hpp), which the
// GUI tests run too.
#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QStringList>
#include <QSurfaceFormat>

#include "ui/shell/studio_launch.hpp"

int main(int argc, char** argv) {
  QCoreApplication::setOrganizationName(QStringLiteral("clm3d"));
  QCoreApplication::setApplicationName(QStringLiteral("clm3d-studio"));
  QCoreApplication::setApplicationVersion(QStringLiteral(CLM3D_VERSION));

  QStringList arguments;
  for (int i = 0; i < argc; ++i) arguments.append(QString::fromLocal8Bit(argv[i]));
  if (const auto exitCode = clm3d::ui::answerWithoutWindow(arguments)) return *exitCode;

  // VTK's widgets need their OpenGL format before the first window exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  return clm3d::ui::runStudio(QApplication::arguments());
}
