#include "ui/train/settings_form.hpp"

#include <QCheckBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QVBoxLayout>
#include <algorithm>
#include <map>
#include <string>
#include <thread>

#include "ui/common/option_fields.hpp"

namespace clm3d::ui {

SettingsForm::SettingsForm(QWidget* parent) : QWidget(parent) {
  // Two columns: views, patches and experts, then the PCA, perturbations and run settings.
  auto* columns = new QHBoxLayout(this);
  columns->setContentsMargins(0, 0, 0, 0);
  auto* first = new QVBoxLayout;
  auto* second = new QVBoxLayout;
  columns->addLayout(first);
  columns->addLayout(second);
  const std::map<std::string, QVBoxLayout*> columnOf = {
      {"Views", first}, {"Patches", first}, {"Experts", first}};
  std::map<std::string, QFormLayout*> groups;
  for (const TrainOption* scoped : optionsFor(trainOptions(), OptionCommand::Train)) {
    const TrainOption& option = *scoped;
    QFormLayout* form = optionGroupForm(groups, option.group, this, [&](QGroupBox* box) {
      const auto column = columnOf.find(option.group);
      (column != columnOf.end() ? column->second : second)->addWidget(box);
    });
    QWidget* field = makeOptionField(option, this, [] {});
    addOptionRow(form, option, field, optionTooltip(option, option.defaultText()));
    fields_.push_back({&option, field});
  }
  first->addStretch(1);
  second->addStretch(1);

  // The single-view baseline has one frontal view: the view lists and mirroring do not apply.
  auto* single = findChild<QCheckBox*>(QStringLiteral("single-view"));
  connect(single, &QCheckBox::toggled, this, [this](bool on) {
    for (const char* name : {"views-yaw", "views-pitch", "no-mirror"}) {
      if (auto* field = findChild<QWidget*>(QLatin1String(name))) field->setEnabled(!on);
    }
  });
  setSettings(TrainSettings{});
}

TrainSettings SettingsForm::settings() const {
  TrainSettings s;
  const bool singleView = findChild<QCheckBox*>(QStringLiteral("single-view"))->isChecked();
  for (const Field& field : fields_) {
    const bool viewList = field.option->kind == OptionKind::RealList;
    if (singleView && viewList) continue;  // ignored by the baseline; kept at the defaults
    field.option->set(s, optionFieldText(field.widget));  // InputError naming the option
  }
  if (s.threads == 0)
    s.threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) - 1);
  s.validate();
  return s;
}

void SettingsForm::setSettings(const TrainSettings& s) {
  for (const Field& field : fields_) setOptionFieldText(field.widget, field.option->get(s));
}

}  // namespace clm3d::ui
