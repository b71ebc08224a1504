#include "core/eval/eval_request.hpp"

#include <optional>
#include <sstream>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/eval/detail/sequence_yaw_bands.hpp"
#include "core/eval/eval_plots.hpp"
#include "core/eval/eval_report.hpp"
#include "core/eval/yaw_bands.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/model_file.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {
namespace eval_request_detail {

namespace fs = std::filesystem;
using R = EvalRequest;

std::vector<Option<R>> makeOptions() {
  const auto path = [](const char* name, const char* help, fs::path R::*field) {
    return textOption<R>(commandOption(name, help), field);
  };
  return {
      textListOption<R>(requiredOption("truth",
                                       "Ground-truth tracks CSV (repeat for several "
                                       "sequences, pooled per tracker)"),
                        &R::truths),
      textListOption<R>(requiredOption("pred",
                                       "Predicted tracks CSV (repeat for several trackers to "
                                       "compare; with N --truth files each tracker gives N, in "
                                       "the truths' order)"),
                        &R::predictions),
      textListOption<R>(commandOption("label",
                                      "Name of each tracker in the report and plots (one "
                                      "per tracker; default: its first file's name)"),
                        &R::labels),
      textOption<R>(
          commandOption("scheme", "Landmark scheme: thesis25, ibug68 or a scheme JSON file"),
          &R::scheme),
      realOption<R>(commandOption("threshold",
                                  "Error at which a point counts as found and a frame as "
                                  "converged",
                                  1e-6, 100.0),
                    &R::threshold),
      realOption<R>(commandOption("wrong-above",
                                  "A frame reported as succeeded with an error above this counts "
                                  "as a wrong success (the tracker said tracked when the fit was "
                                  "off)",
                                  1e-6, 100.0),
                    &R::wrongAbove),
      textOption<R>(commandOption("bucket-by",
                                  "Break the errors down by this ground-truth column (yaw, pitch, "
                                  "roll, frame, ... or an extra column)"),
                    &R::bucketBy),
      flagOption<R>(
          commandOption("bucket-abs", "Bucket by the column's absolute value (e.g. |yaw|)"),
          &R::bucketAbsolute),
      realOption<R>(commandOption("bucket-width",
                                  "Buckets of this width, on multiples of it, covering every "
                                  "frame",
                                  1e-12, 1e12),
                    &R::bucketWidth),
      realListOption<R>(
          commandOption("bucket-edges", "Explicit bucket edges, increasing (e.g. 0,15,30,45,60,80)",
                        -1e12, 1e12),
          &R::bucketEdges),
      path("bucket-csv", "Also write the buckets' figures as CSV (one row per tracker and bucket)",
           &R::bucketCsv),
      textOption<R>(commandOption("yaw-bands",
                                  "Errors per |yaw| band of the truth, edges in degrees (e.g. "
                                  "0,30,60,90): per band the frames, the share tracked, the error "
                                  "over the truth's face box and over the eye distance"),
                    &R::yawBands),
      path("model",
           "With --yaw-bands: a truth frame without a pose gets the yaw of this model fitted to "
           "its points",
           &R::model),
      path("band-table",
           "With --yaw-bands: also write the bands as Markdown, trackers side by side",
           &R::bandTable),
      flagOption<R>(commandOption("json", "Print the report as JSON instead of text"), &R::json),
      path("plot", "Folder for cdf.png, error-per-frame.png and regions.png", &R::plotDir),
      path("out", "Also write the JSON report to this file", &R::out),
  };
}

}  // namespace eval_request_detail

const std::vector<Option<EvalRequest>>& evalOptions() {
  static const std::vector<Option<EvalRequest>> table = eval_request_detail::makeOptions();
  return table;
}

CommandReport runEval(const EvalRequest& args) {
  std::vector<TrackerFiles> trackers;
  try {
    trackers = groupPredictions(args.truths.size(), args.predictions, args.labels);
  } catch (const InputError& e) {
    throw UsageError("--truth/--pred/--label", e.what());
  }
  const bool bucketed = !args.bucketBy.empty();
  if (!bucketed && (args.bucketWidth != 0.0 || !args.bucketEdges.empty() || args.bucketAbsolute ||
                    !args.bucketCsv.empty())) {
    throw UsageError("--bucket-by",
                     "--bucket-width, --bucket-edges, --bucket-abs and --bucket-csv need "
                     "--bucket-by COLUMN");
  }
  if (bucketed && (args.bucketWidth != 0.0) == !args.bucketEdges.empty()) {
    throw UsageError("--bucket-by", "give either --bucket-width W or --bucket-edges A,B,...");
  }
  BucketSpec buckets;
  buckets.column = args.bucketBy;
  buckets.absolute = args.bucketAbsolute;
  buckets.width = args.bucketWidth;
  buckets.edges = args.bucketEdges;

  const bool banded = !args.yawBands.empty();
  if (banded && bucketed)
    throw UsageError("--yaw-bands", "give --yaw-bands or --bucket-by, not both");
  if (!banded && (!args.model.empty() || !args.bandTable.empty())) {
    throw UsageError("--model/--band-table", "--model and --band-table need --yaw-bands");
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
  CommandReport output;
  output.notesToStderr = args.json;
  const std::string json = banded ? formatYawBandReportJson(report) : formatReportJson(report);
  if (args.json) {
    output.text = json;
  } else {
    output.text = formatReportText(report);
    if (banded) output.text += '\n' + formatSequenceYawBands(report);
  }
  std::ostringstream notes;
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
  output.notes = notes.str();
  return output;
}

}  // namespace clm3d
