// clm3d batch: many images and videos with the model loaded once, resumable, sharded, on Slurm;
// `clm3d batch merge` joins shard summaries (docs/batch.md). The job's options and the runs are
// core's (core/track/batch_request); the search and tracker options are the tracker table's Batch
// ones (fit_options). This file also spells the command line each Slurm task runs. Ctrl-C stops
// after the running items, keeping what is finished.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/fit_options.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "app/commands/option_cli.hpp"
#include "core/common/error.hpp"
#include "core/track/batch_request.hpp"

namespace clm3d::cli {
namespace {

// The `clm3d batch` command line each array task runs: this program and every option given here
// but the submission's own.
std::vector<std::string> taskCommand(const CLI::App& command) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) throw Error("cannot find the clm3d program (/proc/self/exe): " + error.message());
  std::vector<std::string> words{self.string(), "batch"};
  const auto& submitOnly = batchSubmitOnlyOptions();
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0 || option->get_lnames().empty()) continue;  // not given, positional
    const std::string name = "--" + option->get_lnames().front();
    if (std::find(submitOnly.begin(), submitOnly.end(), name) != submitOnly.end()) continue;
    if (option->get_expected_min() == 0) {  // a flag
      words.push_back(name);
      continue;
    }
    for (const std::string& value : option->results()) {
      words.push_back(name);
      words.push_back(value);
    }
  }
  return words;
}

}  // namespace

void addBatchCommand(CLI::App& root) {
  auto fit = std::make_shared<FitOptions>();
  CLI::App* command = addRequestCommand(
      root, "batch",
      "fit many images and track many videos with the model loaded once: resumable, sharded, on "
      "Slurm (docs/batch.md)",
      batchRequestOptions(), [fit](BatchRequest& request, const CLI::App& batch) {
        if (batch.get_subcommand("merge")->parsed()) return CommandReport();
        request.tracker = fit->tracker;
        InterruptScope interrupt;
        CliProgress progress(CliProgress::Style::Lines, request.quiet);
        RunReporter reporter;
        reporter.print = [](const std::string& text) { std::cout << text << std::flush; };
        reporter.note = [](const std::string& text) { std::cerr << text; };
        reporter.progress = [&progress](const std::string&) { return progress.callback(); };
        return runBatchRequest(
            request, request.slurmTasks > 0 ? taskCommand(batch) : std::vector<std::string>{},
            reporter, &interrupt.token());
      });
  // The options of `clm3d fit` and of `clm3d track` (core/track/tracker_options): images are
  // fitted, videos tracked; recorded in OUT/options.txt, and a rerun with others is refused.
  addFitOptions(*command, *fit, OptionCommand::Batch);

  auto mergeDir = std::make_shared<std::filesystem::path>();
  CLI::App* merge = command->add_subcommand(
      "merge", "join the shard summaries OUT/summary-I-of-N.csv into OUT/summary.csv");
  merge->add_option("--out-dir", *mergeDir, "the batch's output folder")->required();
  merge->callback([mergeDir] { printOutput(mergeBatchOutputs(*mergeDir)); });
  command->require_subcommand(0, 1);
}

}  // namespace clm3d::cli
