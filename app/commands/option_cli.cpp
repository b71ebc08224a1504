#include "app/commands/option_cli.hpp"

#include <cstdint>
#include <vector>

namespace clm3d::cli {

void addSpecOption(CLI::App& command, const OptionSpec& option, const std::string& defaultText,
                   std::function<void(const std::string&)> set) {
  const std::string flag = "--" + option.name;
  switch (option.kind) {
    case OptionKind::Flag:
      command.add_flag_function(
          flag, [set](std::int64_t count) { set(count > 0 ? "true" : "false"); }, option.help);
      return;
    case OptionKind::RealList:
      // "-60,-30,0" or "-60 -30 0": the items joined by commas; the setter checks each.
      command
          .add_option_function<std::vector<std::string>>(
              flag,
              [set](const std::vector<std::string>& items) {
                std::string text;
                for (const std::string& item : items) text += (text.empty() ? "" : ",") + item;
                set(text);
              },
              option.help + " (each " + optionRangeText(option) + ")")
          ->delimiter(',')
          ->type_name("LIST")
          ->default_str(defaultText);
      return;
    case OptionKind::Integer:
      command
          .add_option_function<std::string>(
              flag, [set](const std::string& text) { set(text); }, option.help)
          ->default_str(defaultText)
          ->type_name("INT")
          ->check(CLI::Range(static_cast<std::int64_t>(option.minimum),
                             static_cast<std::int64_t>(option.maximum)));
      return;
    case OptionKind::Real:
      command
          .add_option_function<std::string>(
              flag, [set](const std::string& text) { set(text); }, option.help)
          ->default_str(defaultText)
          ->type_name("FLOAT")
          ->check(CLI::Range(option.minimum, option.maximum));
      return;
    case OptionKind::Choice:
      command
          .add_option_function<std::string>(
              flag, [set](const std::string& text) { set(text); }, option.help)
          ->default_str(defaultText)
          ->type_name("NAME");
      return;
  }
}

}  // namespace clm3d::cli
