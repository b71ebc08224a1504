// The training settings as a form, built from core's option table (core/train/train_options) with
// the shared option widgets (ui/common/option_fields): one field per option of `clm3d train`,
// grouped as the table groups them, with the table's label, range and a tooltip holding its help,
// command-line name and default, so a run from the studio can be made exactly like one from the
// command line. Each field's object name is the option's name (e.g. "views-yaw").
#pragma once

#include <QWidget>
#include <vector>

#include "core/train/train_options.hpp"
#include "core/train/train_settings.hpp"

namespace clm3d::ui {

class SettingsForm : public QWidget {
  Q_OBJECT
 public:
  explicit SettingsForm(QWidget* parent = nullptr);

  // The settings as entered; throws InputError naming the option when a view list does not parse
  // or the settings are out of range (TrainSettings::validate). Threads 0 becomes every core but
  // one, so that the GUI thread is never starved by the renders.
  TrainSettings settings() const;
  void setSettings(const TrainSettings& settings);

 private:
  struct Field {
    const TrainOption* option;
    QWidget* widget;
  };
  std::vector<Field> fields_;
};

}  // namespace clm3d::ui
