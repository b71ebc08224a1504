#include "app/commands/option_cli.hpp"

#include <cstdint>
#include <vector>

namespace clm3d::cli {

void addSpecOption(CLI::App& command, const OptionSpec& option, const std::string& defaultText,
                   std::function<void(const std::string&)> set) {
  const std::string flag = "--" + option.name;
  if (option.kind == OptionKind::Flag) {
    command.add_flag_function(
        flag, [set](std::int64_t count) { set(count > 0 ? "true" : "false"); }, option.help);
    return;
  }
  if (option.kind == OptionKind::RealList) {
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
  }
  CLI::Option* added = command.add_option_function<std::string>(flag, set, option.help);
  added->default_str(defaultText);
  if (option.kind == OptionKind::Integer && !option.zeroWord.empty()) {
    // "all" or a count (--faces): the setter checks both and names the valid values.
    added->type_name("INT|" + option.zeroWord);
  } else if (option.kind == OptionKind::Integer) {
    added->type_name("INT")->check(CLI::Range(static_cast<std::int64_t>(option.minimum),
                                              static_cast<std::int64_t>(option.maximum)));
  } else if (option.kind == OptionKind::Real) {
    added->type_name("FLOAT")->check(CLI::Range(option.minimum, option.maximum));
  } else {
    added->type_name("NAME");  // a Choice: the setter lists the valid ones
  }
}

}  // namespace clm3d::cli
