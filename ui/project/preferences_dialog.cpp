#include "ui/project/preferences_dialog.hpp"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>

#include "ui/project/studio_settings.hpp"

namespace clm3d::ui {

PreferencesDialog::PreferencesDialog(QWidget* parent) : QDialog(parent) {
  setObjectName(QStringLiteral("preferencesDialog"));
  setWindowTitle(tr("Preferences"));
  const StudioPreferences preferences = loadPreferences();

  autosaveSeconds_ = new QSpinBox;
  autosaveSeconds_->setObjectName(QStringLiteral("autosaveSeconds"));
  autosaveSeconds_->setRange(StudioPreferences::kMinAutosaveSeconds,
                             StudioPreferences::kMaxAutosaveSeconds);
  autosaveSeconds_->setSuffix(tr(" s"));
  autosaveSeconds_->setValue(preferences.autosaveSeconds);
  autosaveSeconds_->setToolTip(
      tr("How often unsaved annotations and ground truth are written to the project's "
         ".clm3d-autosave folders; a crash loses at most this much work."));
  reopenLastProject_ = new QCheckBox(tr("Reopen the last project when the studio starts"));
  reopenLastProject_->setObjectName(QStringLiteral("reopenLastProject"));
  reopenLastProject_->setChecked(preferences.reopenLastProject);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

  auto* form = new QFormLayout(this);
  form->addRow(tr("Autosave every"), autosaveSeconds_);
  form->addRow(reopenLastProject_);
  form->addRow(buttons);
}

void PreferencesDialog::accept() {
  StudioPreferences preferences;
  preferences.autosaveSeconds = autosaveSeconds_->value();
  preferences.reopenLastProject = reopenLastProject_->isChecked();
  savePreferences(preferences);
  QDialog::accept();
}

}  // namespace clm3d::ui
