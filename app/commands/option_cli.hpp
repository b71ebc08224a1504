// Command-line options built from an option table (core/common/option_table.hpp): --NAME with the
// table's help, its default shown in --help and its range checked by CLI11 (bad usage, exit 2),
// the value parsed by the option's own setter (InputError, exit 1). `clm3d fit`, `clm3d track`,
// `clm3d batch` (core/track/tracker_options) and `clm3d train` (core/train/train_options) use it,
// each taking the options scoped to it, so every table-driven option is spelt, limited and
// explained the same way and a command refuses an option its code would not read.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "core/common/option_table.hpp"

namespace clm3d::cli {

// Adds --NAME; `set` receives the value as text (a flag: "true"; a list: its items joined by
// commas). `defaultText` is shown in the help.
void addSpecOption(CLI::App& command, const OptionSpec& option, const std::string& defaultText,
                   std::function<void(const std::string&)> set);

// Adds `option` (an entry of a static table) writing into `settings`, which must outlive the
// command's parsing.
template <typename OptionT, typename Settings>
void addTableOption(CLI::App& command, const OptionT& option, Settings& settings) {
  addSpecOption(command, option, option.defaultText(),
                [&settings, &option](const std::string& text) { option.set(settings, text); });
}

// Adds the options of `table` that `which` takes (OptionSpec::commands), in the table's order.
template <typename OptionT, typename Settings>
void addTableOptions(CLI::App& command, const std::vector<OptionT>& table, OptionCommand which,
                     Settings& settings) {
  for (const OptionT* option : optionsFor(table, which)) addTableOption(command, *option, settings);
}

}  // namespace clm3d::cli
