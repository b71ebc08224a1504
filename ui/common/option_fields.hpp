// The studio's widgets for an option table (core/common/option_table.hpp): one field per option,
// chosen by its kind (spin box with the table's range, check box, combo box of the choices, line
// edit for a list), named after the option and with a tooltip holding its help, command-line name,
// default and range. The Track page's tracker settings and the Train page's training settings are
// built from them, so a form and its command cannot describe an option differently.
#pragma once

#include <QString>
#include <QWidget>
#include <functional>
#include <map>
#include <string>

#include "core/common/option_table.hpp"

class QFormLayout;
class QGroupBox;

namespace clm3d::ui {

// The field of `option`, owned by `parent`; `changed` is called whenever the user edits it.
QWidget* makeOptionField(const OptionSpec& option, QWidget* parent,
                         const std::function<void()>& changed);
// The field's value as the option's text (what Option::set parses) and back.
std::string optionFieldText(const QWidget* field);
void setOptionFieldText(QWidget* field, const std::string& text);
// "help\n\nclm3d fit, track, batch: --name (default D, range A to B)": the commands that take the
// option (OptionSpec::commands).
QString optionTooltip(const OptionSpec& option, const std::string& defaultText);
// The form of the section `group` in `groups` (section name -> form), made on first use: a group
// box titled `group`, owned by `parent`, that `place` puts into the caller's layout.
QFormLayout* optionGroupForm(std::map<std::string, QFormLayout*>& groups, const std::string& group,
                             QWidget* parent, const std::function<void(QGroupBox*)>& place);
// Adds the row (label, field) to `form`, with the tooltip on both; a flag's label is its check
// box's text.
void addOptionRow(QFormLayout* form, const OptionSpec& option, QWidget* field,
                  const QString& tooltip);

}  // namespace clm3d::ui
