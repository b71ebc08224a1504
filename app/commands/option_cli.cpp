#include "app/commands/option_cli.hpp"

#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include "core/common/error.hpp"

namespace clm3d::cli {

void printOutput(const CommandReport& output) {
  std::cerr << output.warnings;
  std::cout << output.text;
  (output.notesToStderr ? std::cerr : std::cout) << output.notes;
  if (!output.failure.empty()) throw InputError(output.failure);
}

CLI::Validator parsedBy(std::function<void(const std::string&)> parse) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          parse(text);
        } catch (const Error& error) {
          return error.what();
        }
        return {};
      },
      "");
}

CLI::Option* addSpecOption(CLI::App& command, const OptionSpec& option,
                           const std::string& defaultText,
                           std::function<void(const std::string&)> set) {
  const std::string flag =
      "--" + option.name + (option.formerName.empty() ? "" : ",--" + option.formerName);
  if (option.kind == OptionKind::Flag) {
    return command.add_flag_function(
        flag, [set](std::int64_t count) { set(count > 0 ? "true" : "false"); }, option.help);
  }
  if (option.repeatable) {
    return command
        .add_option_function<std::vector<std::string>>(
            flag,
            [set](const std::vector<std::string>& items) {
              std::string text;
              for (const std::string& item : items) text += (text.empty() ? "" : "\n") + item;
              set(text);
            },
            option.help)
        ->required(option.required)
        ->default_str(defaultText);
  }
  if (option.kind == OptionKind::RealList) {
    // "-60,-30,0" or "-60 -30 0": the items joined by commas; the setter checks each.
    return command
        .add_option_function<std::vector<std::string>>(
            flag,
            [set](const std::vector<std::string>& items) {
              std::string text;
              for (const std::string& item : items) text += (text.empty() ? "" : ",") + item;
              set(text);
            },
            option.help + (option.maximum > option.minimum
                               ? " (each " + optionRangeText(option) + ")"
                               : std::string()))
        ->delimiter(',')
        ->type_name("LIST")
        ->required(option.required)
        ->default_str(defaultText);
  }
  CLI::Option* added = command.add_option_function<std::string>(flag, set, option.help);
  added->default_str(defaultText)->required(option.required);
  if (option.kind == OptionKind::Integer && !option.zeroWord.empty()) {
    // "all" or a count (--faces): the setter checks both and names the valid values.
    added->type_name("INT|" + option.zeroWord);
  } else if (option.kind == OptionKind::Integer) {
    added->type_name("INT")->check(CLI::Range(static_cast<std::int64_t>(option.minimum),
                                              static_cast<std::int64_t>(option.maximum)));
  } else if (option.kind == OptionKind::Real) {
    added->type_name("FLOAT")->check(CLI::Range(option.minimum, option.maximum));
  } else {
    // A Choice: the setter lists the valid ones; without choices, any text its parser takes.
    added->type_name(option.choices.empty() ? "TEXT" : "NAME");
  }
  return added;
}

}  // namespace clm3d::cli
