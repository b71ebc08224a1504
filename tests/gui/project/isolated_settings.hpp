// Points QSettings at a fresh temporary folder for the life of a GUI test, so tests of the studio's
// preferences and recent projects never read or change the user's own settings.
#pragma once

#include <QCoreApplication>
#include <QSettings>

#include "tests/gui/support/gui_test_support.hpp"

namespace clm3d::test {

class IsolatedSettings {
 public:
  IsolatedSettings() {
    QCoreApplication::setOrganizationName("clm3d");
    QCoreApplication::setApplicationName("clm3d-studio-test");
    const QString path = QString::fromStdString(folder_.path().string());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, path);
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, path);
  }
  const std::filesystem::path& folder() const { return folder_.path(); }
  void clear() { QSettings().clear(); }

 private:
  TempDir folder_;
};

}  // namespace clm3d::test
