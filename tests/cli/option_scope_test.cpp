// Options scoped per command (issue 28 item 2), for every option of every table
// (core/track/tracker_options, core/train/train_options) and every command: given on a command it
// is scoped to, the command line parses and what the command's code receives changes (fit: the
// ImageFitSettings of imageFitSettings, track: the TrackerSettings, batch: the BatchSettings of
// batchSettings, train: the TrainSettings); given on any other command, it is refused. The
// command lines are parsed by the wiring clm3d itself uses (app/commands/fit_options,
// option_cli), and each command's --help, from the clm3d binary, lists exactly its options.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "app/commands/fit_options.hpp"
#include "app/commands/option_cli.hpp"
#include "core/track/batch_run.hpp"
#include "core/train/train_options.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// A valid value of `option` other than its default, as the command line gives it (a flag: none;
// giving it is the change).
std::vector<std::string> otherValue(const OptionSpec& option, const std::string& defaultText) {
  switch (option.kind) {
    case OptionKind::Flag:
      return {};
    case OptionKind::Choice:
      for (const std::string& choice : option.choices) {
        if (choice != defaultText) return {choice};
      }
      break;
    case OptionKind::Integer: {
      const long long low = static_cast<long long>(option.minimum);
      const long long high = static_cast<long long>(option.maximum);
      return {std::to_string(std::to_string(low) != defaultText ? low : high)};
    }
    case OptionKind::Real:
    case OptionKind::RealList: {
      const std::string low = optionRealText(option.minimum);
      return {low != defaultText ? low : optionRealText(option.maximum)};
    }
  }
  ADD_FAILURE() << option.name << ": no value other than its default " << defaultText;
  return {};
}

// Parses `clm3d COMMAND ARGS...` as `which` takes its options; false when refused (CLI11's parse
// error: an option the command does not take).
template <typename Wire>
bool parses(OptionCommand which, const std::vector<std::string>& arguments, Wire wire) {
  CLI::App app;
  CLI::App* command = app.add_subcommand(optionCommandName(which));
  wire(*command);
  std::vector<std::string> words{optionCommandName(which)};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::reverse(words.begin(), words.end());  // CLI11 takes them last first
  try {
    app.parse(words);
  } catch (const CLI::ParseError&) {
    return false;
  }
  return true;
}

// Whether `arguments` parse on `which` and, when they do, whether what its code receives differs
// from what it receives with no option given.
struct Outcome {
  bool parsed = false;
  bool changed = false;
};

Outcome giveTo(OptionCommand which, const std::vector<std::string>& arguments) {
  Outcome outcome;
  if (which == OptionCommand::Train) {
    TrainSettings settings;
    outcome.parsed = parses(which, arguments, [&](CLI::App& command) {
      cli::addTableOptions(command, trainOptions(), which, settings);
    });
    // The trainer receives the TrainSettings: any option changed from its default.
    outcome.changed = !changedOptions(trainOptions(), settings).empty();
    return outcome;
  }
  cli::FitOptions options;
  outcome.parsed = parses(which, arguments,
                          [&](CLI::App& command) { cli::addFitOptions(command, options, which); });
  const cli::FitOptions defaults;
  switch (which) {
    case OptionCommand::Fit:
      outcome.changed = !(imageFitSettings(options.tracker) == imageFitSettings(defaults.tracker));
      break;
    case OptionCommand::Track:
      outcome.changed = !(options.tracker == defaults.tracker);
      break;
    default:
      outcome.changed = !(batchSettings(options.tracker) == batchSettings(defaults.tracker));
      break;
  }
  return outcome;
}

// Whether some option scoped to `which`, of any table, is called `name` (the tracker's --scales and
// the trainer's are two options of one name).
bool takesName(OptionCommand which, const std::string& name) {
  const TrackerOption* tracker = findTrackerOption(name);
  const TrainOption* train = findTrainOption(name);
  return (tracker != nullptr && tracker->commands.has(which)) ||
         (train != nullptr && train->commands.has(which));
}

template <typename OptionT>
int checkTable(const std::vector<OptionT>& table) {
  int checked = 0;
  for (const OptionT& option : table) {
    EXPECT_NE(option.commands.bits, 0u) << option.name << " is scoped to no command";
    const std::vector<std::string> arguments = [&] {
      std::vector<std::string> words{"--" + option.name};
      for (const std::string& value : otherValue(option, option.defaultText())) {
        words.push_back(value);
      }
      return words;
    }();
    for (const OptionCommand which : kOptionCommands) {
      SCOPED_TRACE("clm3d " + std::string(optionCommandName(which)) + " --" + option.name);
      if (!option.commands.has(which) && takesName(which, option.name)) continue;
      const Outcome outcome = giveTo(which, arguments);
      if (option.commands.has(which)) {
        EXPECT_TRUE(outcome.parsed);
        EXPECT_TRUE(outcome.changed) << "the option is taken but its code receives no change";
      } else {
        EXPECT_FALSE(outcome.parsed) << "the option is accepted by a command it is not scoped to";
      }
      ++checked;
    }
  }
  return checked;
}

TEST(OptionScope, EveryOptionChangesWhatItsCommandsReceiveAndOthersRefuseIt) {
  const int checked = checkTable(trackerOptions()) + checkTable(trainOptions());
  std::cout << "[ " << checked << " option x command pairs checked ]\n";
  EXPECT_GT(checked, 100);
}

// The faults issue 28 found: options of a photo's fit that the tracker never reads, and the check's
// threshold that `clm3d fit` could not set.
TEST(OptionScope, TrackRefusesThePhotoFitsOptionsAndFitTakesTheChecksThreshold) {
  for (const char* name : {"tilt-steps", "tilt-step", "wider-search-below", "refine-runs"}) {
    const TrackerOption* option = findTrackerOption(name);
    ASSERT_NE(option, nullptr) << name;
    EXPECT_FALSE(option->commands.has(OptionCommand::Track)) << name;
    EXPECT_TRUE(option->commands.has(OptionCommand::Fit)) << name;
    EXPECT_TRUE(option->commands.has(OptionCommand::Batch)) << name;
  }
  cli::FitOptions options;
  ASSERT_TRUE(
      parses(OptionCommand::Fit, {"--min-check-probability", "0.7"},
             [&](CLI::App& command) { cli::addFitOptions(command, options, OptionCommand::Fit); }));
  EXPECT_DOUBLE_EQ(imageFitSettings(options.tracker).minProbability, 0.7);
}

// --fov, the one search option outside the table, is the camera of what each command runs: the
// tracker's too (it built its camera with the default whatever was given, before issue 28's
// review found it).
TEST(OptionScope, FovChangesWhatFitTrackAndBatchReceive) {
  for (const OptionCommand which :
       {OptionCommand::Fit, OptionCommand::Track, OptionCommand::Batch}) {
    SCOPED_TRACE(optionCommandName(which));
    const Outcome outcome = giveTo(which, {"--fov", "25"});
    EXPECT_TRUE(outcome.parsed);
    EXPECT_TRUE(outcome.changed);
  }
}

// Each command of the clm3d binary takes its scoped options and no other (so a command wired to
// the wrong scope fails here), and says so before loading anything.
TEST(OptionScope, EachCommandsHelpListsExactlyItsOptions) {
  for (const OptionCommand which : kOptionCommands) {
    const std::string name = optionCommandName(which);
    const auto help = test::runClm3d(name + " --help");
    ASSERT_EQ(help.exitCode, 0) << help.output;
    // Listed: its name and its help (`clm3d batch --threads` is the batch's own, not training's).
    const auto listed = [&](const OptionSpec& option) {
      return (test::contains(help.output, "--" + option.name + " ") ||
              test::contains(help.output, "--" + option.name + ",") ||
              test::contains(help.output, "--" + option.name + "\n")) &&
             test::contains(help.output, option.help);
    };
    for (const TrackerOption& option : trackerOptions()) {
      if (takesName(which, option.name) && !option.commands.has(which)) continue;
      EXPECT_EQ(listed(option), option.commands.has(which))
          << "clm3d " << name << " --" << option.name;
    }
    for (const TrainOption& option : trainOptions()) {
      if (takesName(which, option.name) && !option.commands.has(which)) continue;
      EXPECT_EQ(listed(option), option.commands.has(which))
          << "clm3d " << name << " --" << option.name;
    }
  }
  const auto refused = test::runClm3d(
      "track --model m.clm3d --video v.mp4 --out t.csv "
      "--tilt-steps 1");
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_TRUE(test::contains(refused.output, "tilt-steps")) << refused.output;
}

}  // namespace
}  // namespace clm3d
