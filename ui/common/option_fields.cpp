#include "ui/common/option_fields.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QStringList>
#include <cmath>

namespace clm3d::ui {
namespace {

QString qText(const std::string& text) {
  return QString::fromStdString(text);
}

}  // namespace

QWidget* makeOptionField(const OptionSpec& option, QWidget* parent,
                         const std::function<void()>& changed) {
  QWidget* widget = nullptr;
  switch (option.kind) {
    case OptionKind::Integer: {
      auto* spin = new QSpinBox(parent);
      spin->setRange(static_cast<int>(option.minimum), static_cast<int>(option.maximum));
      if (!option.zeroWord.empty()) {
        // The word ("all") is the value 0, one step below the range.
        spin->setMinimum(0);
        spin->setSpecialValueText(qText(option.zeroWord));
      }
      QObject::connect(spin, QOverload<int>::of(&QSpinBox::valueChanged), parent,
                       [changed] { changed(); });
      widget = spin;
      break;
    }
    case OptionKind::Real: {
      auto* spin = new QDoubleSpinBox(parent);
      spin->setDecimals(option.decimals);
      spin->setRange(option.minimum, option.maximum);
      spin->setSingleStep(std::pow(10.0, -option.decimals) * 5.0);
      QObject::connect(spin, QOverload<double>::of(&QDoubleSpinBox::valueChanged), parent,
                       [changed] { changed(); });
      widget = spin;
      break;
    }
    case OptionKind::Flag: {
      auto* check = new QCheckBox(qText(option.label), parent);
      QObject::connect(check, &QCheckBox::toggled, parent, [changed] { changed(); });
      widget = check;
      break;
    }
    case OptionKind::Choice: {
      auto* combo = new QComboBox(parent);
      for (const std::string& c : option.choices) combo->addItem(qText(c));
      QObject::connect(combo, QOverload<int>::of(&QComboBox::currentIndexChanged), parent,
                       [changed] { changed(); });
      widget = combo;
      break;
    }
    case OptionKind::RealList: {
      auto* edit = new QLineEdit(parent);
      QObject::connect(edit, &QLineEdit::textEdited, parent, [changed] { changed(); });
      widget = edit;
      break;
    }
  }
  widget->setObjectName(qText(option.name));
  return widget;
}

std::string optionFieldText(const QWidget* field) {
  if (const auto* spin = qobject_cast<const QSpinBox*>(field)) {
    if (spin->value() == spin->minimum() && !spin->specialValueText().isEmpty()) {
      return spin->specialValueText().toStdString();  // an option's zeroWord
    }
    return std::to_string(spin->value());
  }
  if (const auto* real = qobject_cast<const QDoubleSpinBox*>(field)) {
    // 15 significant digits: the shortest text of a value with the field's few decimals.
    return QString::number(real->value(), 'g', 15).toStdString();
  }
  if (const auto* check = qobject_cast<const QCheckBox*>(field)) {
    return check->isChecked() ? "true" : "false";
  }
  if (const auto* combo = qobject_cast<const QComboBox*>(field)) {
    return combo->currentText().toStdString();
  }
  if (const auto* edit = qobject_cast<const QLineEdit*>(field)) return edit->text().toStdString();
  return {};
}

void setOptionFieldText(QWidget* field, const std::string& value) {
  const QString text = qText(value);
  if (auto* spin = qobject_cast<QSpinBox*>(field)) {
    spin->setValue(text.toInt());
  } else if (auto* real = qobject_cast<QDoubleSpinBox*>(field)) {
    real->setValue(text.toDouble());
  } else if (auto* check = qobject_cast<QCheckBox*>(field)) {
    check->setChecked(text == QStringLiteral("true"));
  } else if (auto* combo = qobject_cast<QComboBox*>(field)) {
    combo->setCurrentIndex(combo->findText(text));
  } else if (auto* edit = qobject_cast<QLineEdit*>(field)) {
    // "-60,-30,0" shown as "-60, -30, 0".
    edit->setText(text.split(QLatin1Char(',')).join(QStringLiteral(", ")));
  }
}

QString optionTooltip(const OptionSpec& option, const std::string& defaultText) {
  QString range;
  if (option.kind == OptionKind::Integer || option.kind == OptionKind::Real) {
    range = QObject::tr(", range %1 to %2").arg(option.minimum).arg(option.maximum);
    if (!option.zeroWord.empty()) range += QObject::tr(" or %1").arg(qText(option.zeroWord));
  } else if (option.kind == OptionKind::RealList) {
    range = QObject::tr(", each within %1 to %2").arg(option.minimum).arg(option.maximum);
  } else if (option.kind == OptionKind::Choice) {
    QStringList choices;
    for (const std::string& c : option.choices) choices << qText(c);
    range = QObject::tr(", one of %1").arg(choices.join(QStringLiteral(", ")));
  }
  return QObject::tr("%1\n\nclm3d %2: --%3 (default %4%5)")
      .arg(qText(option.help), qText(optionCommandsText(option.commands)), qText(option.name),
           qText(defaultText), range);
}

QFormLayout* optionGroupForm(std::map<std::string, QFormLayout*>& groups, const std::string& group,
                             QWidget* parent, const std::function<void(QGroupBox*)>& place) {
  QFormLayout*& form = groups[group];
  if (form == nullptr) {
    auto* box = new QGroupBox(qText(group), parent);
    form = new QFormLayout(box);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    place(box);
  }
  return form;
}

void addOptionRow(QFormLayout* form, const OptionSpec& option, QWidget* field,
                  const QString& tooltip) {
  field->setToolTip(tooltip);
  if (option.kind == OptionKind::Flag) {
    form->addRow(field);
    return;
  }
  auto* label = new QLabel(qText(option.label), field->parentWidget());
  label->setToolTip(tooltip);
  label->setBuddy(field);
  form->addRow(label, field);
}

}  // namespace clm3d::ui
