// clm3d eval: compares one or more trackers' tracks CSVs against ground truth with the error of
// thesis eq. 5.1 (docs/evaluation.md) and prints each prediction's summary, then Welch's t-test
// (two predictions) or one-way ANOVA (three or more); several sequences pool per tracker (repeated
// --truth, each tracker's --pred files in the same order); optionally the errors bucketed by a
// truth column (e.g. |yaw|), JSON, plots and report files. Everything is core/eval/eval_report.hpp.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/eval/eval_plots.hpp"
#include "core/eval/eval_report.hpp"
#include "core/eval/sequence_yaw_bands.hpp"
#include "core/eval/yaw_bands.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/model_file.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct EvalArgs {
  std::vector<fs::path> truths;
  std::vector<fs::path> predictions;
  std::vector<std::string> labels;
  std::string scheme = "thesis25";
  bool json = false;
  fs::path plotDir;
  fs::path out;
  double threshold = 0.18;
  double wrongAbove = 0.3;
  std::string bucketBy;
  bool bucketAbsolute = false;
  double bucketWidth = 0.0;
  std::vector<double> bucketEdges;
  fs::path bucketCsv;
  std::string yawBands;
  fs::path model;
  fs::path bandTable;
};

void runEval(const EvalArgs& args) {
  std::vector<TrackerFiles> trackers;
  try {
    trackers = groupPredictions(args.truths.size(), args.predictions, args.labels);
  } catch (const InputError& e) {
    throw CLI::ValidationError("--truth/--pred/--label", e.what());
  }
  const bool bucketed = !args.bucketBy.empty();
  if (!bucketed && (args.bucketWidth != 0.0 || !args.bucketEdges.empty() || args.bucketAbsolute ||
                    !args.bucketCsv.empty())) {
    throw CLI::ValidationError("--bucket-by",
                               "--bucket-width, --bucket-edges, --bucket-abs and --bucket-csv "
                               "need --bucket-by COLUMN");
  }
  if (bucketed && (args.bucketWidth != 0.0) == !args.bucketEdges.empty()) {
    throw CLI::ValidationError("--bucket-by",
                               "give either --bucket-width W or --bucket-edges A,B,...");
  }
  BucketSpec buckets;
  buckets.column = args.bucketBy;
  buckets.absolute = args.bucketAbsolute;
  buckets.width = args.bucketWidth;
  buckets.edges = args.bucketEdges;

  const bool banded = !args.yawBands.empty();
  if (banded && bucketed) {
    throw CLI::ValidationError("--yaw-bands", "give --yaw-bands or --bucket-by, not both");
  }
  if (!banded && (!args.model.empty() || !args.bandTable.empty())) {
    throw CLI::ValidationError("--model/--band-table", "--model and --band-table need --yaw-bands");
  }

  const Scheme scheme = Scheme::byNameOrPath(args.scheme);
  EvalOptions options;
  options.threshold = args.threshold;
  options.wrongAbove = args.wrongAbove;
  EvaluationReport report;
  if (banded) {
    std::optional<ClmModel> model;
    if (!args.model.empty()) model = loadModel(args.model);
    report = evaluateTrackFilesByYaw(args.truths, trackers, scheme, options,
                                     parseBandEdges(args.yawBands), model ? &*model : nullptr,
                                     kDefaultVerticalFovDeg);
  } else {
    report =
        evaluateTrackFiles(args.truths, trackers, scheme, options, bucketed ? &buckets : nullptr);
  }

  // With --json, stdout holds only the JSON document; where files went is said on stderr.
  std::ostream& notes = args.json ? std::cerr : std::cout;
  const std::string json = banded ? formatYawBandReportJson(report) : formatReportJson(report);
  if (args.json) {
    std::cout << json;
  } else {
    std::cout << formatReportText(report);
    if (banded) std::cout << '\n' << formatSequenceYawBands(report);
  }
  if (!args.out.empty()) {
    writeTextAtomically(args.out, json);
    notes << "report: " << args.out.string() << '\n';
  }
  if (!args.bandTable.empty()) {
    writeTextAtomically(args.bandTable, formatSequenceYawBandMarkdown(report));
    notes << "band table: " << args.bandTable.string() << '\n';
  }
  if (!args.bucketCsv.empty()) {
    writeBucketsCsv(args.bucketCsv, report);
    notes << "buckets: " << args.bucketCsv.string() << '\n';
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
      "convergence, regions, errors by pose, significance tests and plots");
  command
      ->add_option("--truth", args->truths,
                   "Ground-truth tracks CSV (repeat for several sequences, pooled per tracker)")
      ->required();
  command
      ->add_option("--pred", args->predictions,
                   "Predicted tracks CSV (repeat for several trackers to compare; with N --truth "
                   "files each tracker gives N, in the truths' order)")
      ->required();
  command->add_option("--label", args->labels,
                      "Name of each tracker in the report and plots (one per tracker; default: "
                      "its first file's name)");
  command
      ->add_option("--scheme", args->scheme,
                   "Landmark scheme: thesis25, ibug68 or a scheme JSON file")
      ->default_val("thesis25");
  command
      ->add_option("--threshold", args->threshold,
                   "Error at which a point counts as found and a frame as converged")
      ->default_val(0.18)
      ->check(CLI::Range(1e-6, 100.0));
  command
      ->add_option("--wrong-above", args->wrongAbove,
                   "A frame reported as succeeded with an error above this counts as a wrong "
                   "success (the tracker said tracked when the fit was off)")
      ->default_val(0.3)
      ->check(CLI::Range(1e-6, 100.0));
  command->add_option("--bucket-by", args->bucketBy,
                      "Break the errors down by this ground-truth column (yaw, pitch, roll, "
                      "frame, ... or an extra column)");
  command->add_flag("--bucket-abs", args->bucketAbsolute,
                    "Bucket by the column's absolute value (e.g. |yaw|)");
  command
      ->add_option("--bucket-width", args->bucketWidth,
                   "Buckets of this width, on multiples of it, covering every frame")
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--bucket-edges", args->bucketEdges,
                   "Explicit bucket edges, increasing (e.g. 0,15,30,45,60,80)")
      ->delimiter(',');
  command->add_option("--bucket-csv", args->bucketCsv,
                      "Also write the buckets' figures as CSV (one row per tracker and bucket)");
  command->add_option("--yaw-bands", args->yawBands,
                      "Errors per |yaw| band of the truth, edges in degrees (e.g. 0,30,60,90): "
                      "per band the frames, the share tracked, the error over the truth's face "
                      "box and over the eye distance");
  command->add_option("--model", args->model,
                      "With --yaw-bands: a truth frame without a pose gets the yaw of this model "
                      "fitted to its points");
  command->add_option("--band-table", args->bandTable,
                      "With --yaw-bands: also write the bands as Markdown, trackers side by side");
  command->add_flag("--json", args->json, "Print the report as JSON instead of text");
  command->add_option("--plot", args->plotDir,
                      "Folder for cdf.png, error-per-frame.png and regions.png");
  command->add_option("--out", args->out, "Also write the JSON report to this file");
  command->callback([args] { runEval(*args); });
}

}  // namespace clm3d::cli
