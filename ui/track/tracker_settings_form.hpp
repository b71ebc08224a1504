// The tracker's settings as a form, built from core's option table (core/track/tracker_options)
// with the shared option widgets (ui/common/option_fields):
// one field per option, grouped as the table groups them, labelled with the table's label and
// with a tooltip holding its help, command-line name, default and range, so the studio and
// `clm3d track` cannot describe an option differently. Each field's object name is the option's
// name. The dialog around it is what the Track page's "Settings…" button opens.
#pragma once

#include <QDialog>
#include <QWidget>
#include <vector>

#include "core/track/tracker.hpp"

namespace clm3d {
struct TrackerOption;
}

namespace clm3d::ui {

class TrackerSettingsForm : public QWidget {
  Q_OBJECT
 public:
  explicit TrackerSettingsForm(QWidget* parent = nullptr);

  void setSettings(const TrackerSettings& settings);
  // The defaults with every field's value applied.
  TrackerSettings settings() const;
  // The tooltip of an option's field (its help, --name, default and range).
  static QString tooltipFor(const TrackerOption& option);

 signals:
  void changed();

 private:
  struct Field {
    const TrackerOption* option;
    QWidget* widget;
  };
  std::vector<Field> fields_;
};

class TrackerSettingsDialog : public QDialog {
  Q_OBJECT
 public:
  explicit TrackerSettingsDialog(const TrackerSettings& settings, QWidget* parent = nullptr);
  TrackerSettings settings() const;
  TrackerSettingsForm* form() { return form_; }

 private:
  TrackerSettingsForm* form_;
};

}  // namespace clm3d::ui
