// clm3d eval: compares one or more tracks CSVs against a ground-truth one with the error of thesis
// eq. 5.1 (docs/evaluation.md) and prints each prediction's summary, then Welch's t-test (two
// predictions) or one-way ANOVA (three or more); optionally JSON, plots and a report file.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "core/eval/eval_plots.hpp"
#include "core/eval/eval_report.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct EvalArgs {
  fs::path truth;
  std::vector<fs::path> predictions;
  std::vector<std::string> labels;
  std::string scheme = "thesis25";
  bool json = false;
  fs::path plotDir;
  fs::path out;
  double threshold = 0.18;
};

void runEval(const EvalArgs& args) {
  const Scheme scheme = Scheme::byNameOrPath(args.scheme);
  EvalOptions options;
  options.threshold = args.threshold;
  const auto report =
      evaluateTrackFiles(args.truth, args.predictions, args.labels, scheme, options);

  // With --json, stdout holds only the JSON document; where files went is said on stderr.
  std::ostream& notes = args.json ? std::cerr : std::cout;
  if (args.json) {
    std::cout << formatReportJson(report);
  } else {
    std::cout << formatReportText(report);
  }
  if (!args.out.empty()) {
    writeReportJson(args.out, report);
    notes << "report: " << args.out.string() << '\n';
  }
  if (!args.plotDir.empty()) {
    const auto files = writeEvaluationPlots(args.plotDir, report);
    notes << "plots:";
    for (const auto& file : files) notes << ' ' << file.string();
    notes << '\n';
  }
}

}  // namespace

void addEvalCommand(CLI::App& root) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* command = root.add_subcommand(
      "eval",
      "Compare tracker outputs (tracks CSV) with ground truth: error of thesis eq. 5.1, "
      "convergence, regions, significance tests and plots");
  command->add_option("--truth", args->truth, "Ground-truth tracks CSV")->required();
  command
      ->add_option("--pred", args->predictions,
                   "Predicted tracks CSV (repeat for several trackers to compare)")
      ->required();
  command->add_option("--label", args->labels,
                      "Name of each prediction in the report and plots (one per --pred; "
                      "default: the file name)");
  command
      ->add_option("--scheme", args->scheme,
                   "Landmark scheme: thesis25, ibug68 or a scheme JSON file")
      ->default_val("thesis25");
  command
      ->add_option("--threshold", args->threshold,
                   "Error at which a point counts as found and a frame as converged")
      ->default_val(0.18)
      ->check(CLI::Range(1e-6, 100.0));
  command->add_flag("--json", args->json, "Print the report as JSON instead of text");
  command->add_option("--plot", args->plotDir,
                      "Folder for cdf.png, error-per-frame.png and regions.png");
  command->add_option("--out", args->out, "Also write the JSON report to this file");
  command->callback([args] { runEval(*args); });
}

}  // namespace clm3d::cli
