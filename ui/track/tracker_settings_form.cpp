#include "ui/track/tracker_settings_form.hpp"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>
#include <map>
#include <string>

#include "core/track/tracker_options.hpp"
#include "ui/common/option_fields.hpp"

namespace clm3d::ui {

QString TrackerSettingsForm::tooltipFor(const TrackerOption& option) {
  return optionTooltip(option, option.defaultText());
}

TrackerSettingsForm::TrackerSettingsForm(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  std::map<std::string, QFormLayout*> groups;
  // The options of `clm3d track`: the ones a photo's fit alone reads are not the tracker's.
  for (const TrackerOption* scoped : optionsFor(trackerOptions(), OptionCommand::Track)) {
    const TrackerOption& option = *scoped;
    QFormLayout* form = optionGroupForm(groups, option.group, this,
                                        [layout](QGroupBox* box) { layout->addWidget(box); });
    QWidget* widget = makeOptionField(option, this, [this] { emit changed(); });
    addOptionRow(form, option, widget, tooltipFor(option));
    fields_.push_back({&option, widget});
  }
  layout->addStretch(1);
  setSettings(TrackerSettings{});
}

void TrackerSettingsForm::setSettings(const TrackerSettings& settings) {
  for (const Field& field : fields_) setOptionFieldText(field.widget, field.option->get(settings));
}

TrackerSettings TrackerSettingsForm::settings() const {
  TrackerSettings settings;
  for (const Field& field : fields_) {
    field.option->set(settings, optionFieldText(field.widget));  // the fields hold valid values
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
