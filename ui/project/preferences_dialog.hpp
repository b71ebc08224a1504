// File > Preferences: edits the studio's preferences (studio_settings.hpp) and saves them to
// QSettings when accepted, so the autosave interval and reopening the last project are the user's
// choice.
#pragma once

#include <QDialog>

class QCheckBox;
class QSpinBox;

namespace clm3d::ui {

class PreferencesDialog : public QDialog {
  Q_OBJECT
 public:
  explicit PreferencesDialog(QWidget* parent = nullptr);

  void accept() override;

 private:
  QSpinBox* autosaveSeconds_ = nullptr;
  QCheckBox* reopenLastProject_ = nullptr;
};

}  // namespace clm3d::ui
