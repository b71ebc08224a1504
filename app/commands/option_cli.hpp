// Command-line options built from an option table (core/common/option_table.hpp): --NAME with the
// table's help, its default shown in --help and its range checked by CLI11 (bad usage, exit 2),
// the value parsed by the option's own setter (InputError, exit 1). `clm3d fit`, `clm3d track`,
// `clm3d batch` (core/track/tracker_options) and `clm3d train` (core/train/train_options) use it,
// each taking the options scoped to it, so every table-driven option is spelt, limited and
// explained the same way and a command refuses an option its code would not read. The other
// commands are requests in core (core/STAGE/NAME_request: a struct, its table, its run) added
// with addRequestCommand, whose every bad value is bad usage (exit 2) and whose output core
// returns for printOutput to print.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/common/command_report.hpp"
#include "core/common/option_table.hpp"

namespace clm3d::cli {

// Adds --NAME; `set` receives the value as text (a flag: "true"; a list: its items joined by
// commas; a repeatable option: its values one a line). `defaultText` is shown in the help.
CLI::Option* addSpecOption(CLI::App& command, const OptionSpec& option,
                           const std::string& defaultText,
                           std::function<void(const std::string&)> set);

// A check that runs `parse` on each value as CLI11 reads it: a clm3d::Error it throws is bad usage.
CLI::Validator parsedBy(std::function<void(const std::string&)> parse);

// Adds `option` (an entry of a static table) writing into `settings`, which must outlive the
// command's parsing.
template <typename OptionT, typename Settings>
CLI::Option* addTableOption(CLI::App& command, const OptionT& option, Settings& settings) {
  return addSpecOption(
      command, option, option.defaultText(),
      [&settings, &option](const std::string& text) { option.set(settings, text); });
}

// Adds every option of a command's own table (the request core reads, e.g. core/eval/
// synth_request) writing into `settings`, which must outlive the parsing. Each value goes through
// its option's parser while the command line is read, so a value it does not take is bad usage
// (exit 2), as a CLI11 check is.
template <typename Settings>
void addCommandOptions(CLI::App& command, const std::vector<Option<Settings>>& table,
                       Settings& settings) {
  for (const Option<Settings>& option : table) {
    CLI::Option* added = addTableOption(command, option, settings);
    if (option.kind == OptionKind::Flag) continue;
    added->check(parsedBy([&option](const std::string& text) {
      Settings scratch;
      option.set(scratch, text);
    }));
  }
}

// Adds the options of `table` that `which` takes (OptionSpec::commands), in the table's order.
template <typename OptionT, typename Settings>
void addTableOptions(CLI::App& command, const std::vector<OptionT>& table, OptionCommand which,
                     Settings& settings) {
  for (const OptionT* option : optionsFor(table, which)) addTableOption(command, *option, settings);
}

// The options of `table` given on the command line, by name (after parsing).
template <typename OptionT>
std::set<std::string> givenOptions(const CLI::App& command, const std::vector<OptionT>& table) {
  std::set<std::string> given;
  for (const OptionT& option : table) {
    if (command.count("--" + option.name) > 0) given.insert(option.name);
  }
  return given;
}

// Prints a core run's output: its warnings on stderr, its text on stdout, its notes after it (on
// stderr with --json); then throws its failure as an InputError (exit 1).
void printOutput(const CommandReport& output);

// Adds subcommand `name` whose options are all those of a command's own table (addCommandOptions)
// and whose callback prints what run(request, command) returns (a CommandReport or a string),
// with the request they filled. The request lives as long as the command.
template <typename Settings, typename Run>
CLI::App* addRequestCommand(CLI::App& root, const std::string& name, const std::string& description,
                            const std::vector<Option<Settings>>& table, Run run) {
  auto request = std::make_shared<Settings>();
  CLI::App* command = root.add_subcommand(name, description);
  addCommandOptions(*command, table, *request);
  command->callback([request, command, run] { printOutput(run(*request, *command)); });
  return command;
}

}  // namespace clm3d::cli
