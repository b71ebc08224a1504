#include "ui/track/tracker_settings_form.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QVBoxLayout>
#include <cmath>
#include <map>
#include <string>

#include "core/track/tracker_options.hpp"

namespace clm3d::ui {
namespace {

QString qText(const std::string& text) {
  return QString::fromStdString(text);
}

}  // namespace

QString TrackerSettingsForm::tooltipFor(const TrackerOption& option) {
  QString range;
  if (option.kind == OptionKind::Integer || option.kind == OptionKind::Real) {
    range = tr(", range %1 to %2").arg(option.minimum).arg(option.maximum);
  } else if (option.kind == OptionKind::Choice) {
    QStringList choices;
    for (const std::string& c : option.choices) choices << qText(c);
    range = tr(", one of %1").arg(choices.join(QStringLiteral(", ")));
  }
  return tr("%1\n\nclm3d track --%2 (default %3%4)")
      .arg(qText(option.help), qText(option.name), qText(option.defaultText()), range);
}

TrackerSettingsForm::TrackerSettingsForm(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  std::map<std::string, QFormLayout*> groups;
  for (const TrackerOption& option : trackerOptions()) {
    QFormLayout*& form = groups[option.group];
    if (form == nullptr) {
      auto* box = new QGroupBox(qText(option.group), this);
      form = new QFormLayout(box);
      layout->addWidget(box);
    }
    QWidget* widget = nullptr;
    switch (option.kind) {
      case OptionKind::Integer: {
        auto* spin = new QSpinBox(this);
        spin->setRange(static_cast<int>(option.minimum), static_cast<int>(option.maximum));
        connect(spin, QOverload<int>::of(&QSpinBox::valueChanged), this,
                &TrackerSettingsForm::changed);
        widget = spin;
        break;
      }
      case OptionKind::Real: {
        auto* spin = new QDoubleSpinBox(this);
        spin->setDecimals(option.decimals);
        spin->setRange(option.minimum, option.maximum);
        spin->setSingleStep(std::pow(10.0, -option.decimals) * 5.0);
        connect(spin, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
                &TrackerSettingsForm::changed);
        widget = spin;
        break;
      }
      case OptionKind::Flag: {
        auto* check = new QCheckBox(this);
        connect(check, &QCheckBox::toggled, this, &TrackerSettingsForm::changed);
        widget = check;
        break;
      }
      case OptionKind::Choice: {
        auto* combo = new QComboBox(this);
        for (const std::string& c : option.choices) combo->addItem(qText(c));
        connect(combo, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
                &TrackerSettingsForm::changed);
        widget = combo;
        break;
      }
    }
    widget->setObjectName(qText(option.name));
    const QString tooltip = tooltipFor(option);
    widget->setToolTip(tooltip);
    auto* label = new QLabel(qText(option.label), this);
    label->setToolTip(tooltip);
    label->setBuddy(widget);
    form->addRow(label, widget);
    fields_.push_back({&option, widget});
  }
  // --- Smoothing: its options join the table in core (group "Smoothing") and appear here. ---
  layout->addStretch(1);
  setSettings(TrackerSettings{});
}

void TrackerSettingsForm::setSettings(const TrackerSettings& settings) {
  for (const Field& field : fields_) {
    const QString text = qText(field.option->get(settings));
    if (auto* spin = qobject_cast<QSpinBox*>(field.widget)) {
      spin->setValue(text.toInt());
    } else if (auto* real = qobject_cast<QDoubleSpinBox*>(field.widget)) {
      real->setValue(text.toDouble());
    } else if (auto* check = qobject_cast<QCheckBox*>(field.widget)) {
      check->setChecked(text == QStringLiteral("true"));
    } else if (auto* combo = qobject_cast<QComboBox*>(field.widget)) {
      combo->setCurrentIndex(combo->findText(text));
    }
  }
}

TrackerSettings TrackerSettingsForm::settings() const {
  TrackerSettings settings;
  for (const Field& field : fields_) {
    std::string text;
    if (auto* spin = qobject_cast<QSpinBox*>(field.widget)) {
      text = std::to_string(spin->value());
    } else if (auto* real = qobject_cast<QDoubleSpinBox*>(field.widget)) {
      // 15 significant digits: the shortest text of a value with the field's few decimals.
      text = QString::number(real->value(), 'g', 15).toStdString();
    } else if (auto* check = qobject_cast<QCheckBox*>(field.widget)) {
      text = check->isChecked() ? "true" : "false";
    } else if (auto* combo = qobject_cast<QComboBox*>(field.widget)) {
      text = combo->currentText().toStdString();
    }
    field.option->set(settings, text);  // the fields only hold valid values
  }
  return settings;
}

TrackerSettingsDialog::TrackerSettingsDialog(const TrackerSettings& settings, QWidget* parent)
    : QDialog(parent), form_(new TrackerSettingsForm(this)) {
  setObjectName(QStringLiteral("trackerSettingsDialog"));
  setWindowTitle(tr("Tracker settings"));
  form_->setSettings(settings);
  auto* scroll = new QScrollArea(this);
  scroll->setWidget(form_);
  scroll->setWidgetResizable(true);
  auto* note = new QLabel(
      tr("The options of <tt>clm3d track</tt>, under the same names (hover a field for its "
         "help). They are remembered in the project."),
      this);
  note->setWordWrap(true);
  auto* buttons = new QDialogButtonBox(
      QDialogButtonBox::Ok | QDialogButtonBox::Cancel | QDialogButtonBox::RestoreDefaults, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
          [this] { form_->setSettings(TrackerSettings{}); });
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(note);
  layout->addWidget(scroll, 1);
  layout->addWidget(buttons);
  resize(480, 640);
}

TrackerSettings TrackerSettingsDialog::settings() const {
  return form_->settings();
}

}  // namespace clm3d::ui
