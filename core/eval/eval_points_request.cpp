#include "core/eval/eval_points_request.hpp"

#include <sstream>
#include <stdexcept>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/eval/detail/confidence_roc.hpp"
#include "core/eval/landmark_error.hpp"
#include "core/eval/point_folder_error.hpp"
#include "core/eval/point_set_error.hpp"
#include "core/eval/yaw_bands.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/model_file.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {
namespace eval_points_request_detail {

namespace fs = std::filesystem;
using R = EvalPointsRequest;

std::vector<Option<R>> makeOptions() {
  const auto path = [](const char* name, const char* help, fs::path R::*field) {
    return textOption<R>(commandOption(name, help), field);
  };
  const auto paths = [](const char* name, const char* help, std::vector<fs::path> R::*field) {
    return textListOption<R>(commandOption(name, help), field);
  };
  return {
      path("truth", "True points (.pts, .ljson, .csv; a 68-point file is converted to thesis25)",
           &R::truth),
      paths("pred", "Predicted points (repeat to compare several)", &R::predictions),
      path("truth-dir",
           "Folder of true points STEM.pts, one per image, instead of --truth: the scheme's "
           "points, or for thesis25 68 (iBUG) or 21 (AFLW, invisible points \"-1 -1\") paired "
           "with its points; the face box is that of each file's own points",
           &R::truthDir),
      paths("pred-dir",
            "Folder of predictions STEM.pts, .ljson or .csv (repeat to compare methods); an image "
            "without one counts as a failure",
            &R::predictionDirs),
      textListOption<R>(
          commandOption("label", "Name of each prediction (one per --pred or --pred-dir)"),
          &R::labels),
      path("csv", "With --truth-dir: write one row per image and method to this CSV", &R::csv),
      textOption<R>(commandOption("points",
                                  "Points to score: 1-based numbers, ranges and ids, "
                                  "e.g. 1-18,22 (default: all)"),
                    &R::points),
      textOption<R>(commandOption("scheme", "Landmark scheme: thesis25, ibug68 or a scheme JSON"),
                    &R::scheme),
      realOption<R>(
          commandOption("threshold", "Error at which a point counts as found", 1e-6, 100.0),
          &R::threshold),
      flagOption<R>(commandOption("json", "Print the report as JSON instead of text"), &R::json),
      flagOption<R>(commandOption("same-faces",
                                  "With --truth-dir: score only the images that every --pred-dir "
                                  "fitted (a prediction its summary.csv does not mark rejected), "
                                  "so that methods are compared on the same faces"),
                    &R::sameFaces),
      flagOption<R>(commandOption("roc",
                                  "With --pred-dir folders written by clm3d fit --images: how "
                                  "well the fits' confidence (their summary.csv) tells right fits "
                                  "from wrong ones"),
                    &R::roc),
      realOption<R>(commandOption("wrong-above",
                                  "For --roc: a fit whose error exceeds this is wrong", 0.0, 10.0),
                    &R::wrongAbove),
      realOption<R>(commandOption("accept-at",
                                  "For --roc: also count the fits kept and accepted at this "
                                  "confidence (default: the default of --min-probability)",
                                  0.0, 1.0),
                    &R::acceptAt),
      path("poses",
           "With --truth-dir: CSV with columns image,yaw_deg (e.g. AFLW's index.csv); adds the "
           "per-|yaw|-band table",
           &R::poses),
      path("model",
           "With --truth-dir and no --poses: each truth's yaw is that of this model fitted to its "
           "points (the model's scheme must be --scheme)",
           &R::model),
      textOption<R>(commandOption("yaw-bands",
                                  "Edges of the |yaw| bands in degrees, ascending, e.g. 0,45,90"),
                    &R::yawBands),
      realOption<R>(commandOption("off-face-above",
                                  "With yaw bands: a fitted face whose error over its face box "
                                  "exceeds this counts as off the face",
                                  0.0, 10.0),
                    &R::offFaceAbove),
      path("band-table",
           "With --poses or --model: write the band table as Markdown, the methods side by side "
           "(faces fitted and error / face box per |yaw| band)",
           &R::bandTable),
      path("out", "Also write the JSON report to this file", &R::out),
  };
}

void checkCombination(const R& args) {
  const bool files = !args.truth.empty() || !args.predictions.empty();
  const bool folders = !args.truthDir.empty() || !args.predictionDirs.empty();
  if (files == folders) {
    throw UsageError("--truth/--truth-dir",
                     "give --truth A.pts --pred B.pts (one image) or --truth-dir DIR --pred-dir "
                     "DIR (folders paired by file stem)");
  }
  if (files && (args.truth.empty() || args.predictions.empty())) {
    throw UsageError("--truth/--pred", "one image needs both --truth and --pred");
  }
  if (folders && (args.truthDir.empty() || args.predictionDirs.empty())) {
    throw UsageError("--truth-dir/--pred-dir", "folders need both --truth-dir and --pred-dir");
  }
  if (files && args.roc) throw UsageError("--roc", "the confidence ROC goes with --truth-dir");
  if (files && (!args.poses.empty() || !args.model.empty())) {
    throw UsageError("--poses", "the yaw-band table goes with --truth-dir");
  }
  if (folders && !args.bandTable.empty() && args.poses.empty() && args.model.empty()) {
    throw UsageError("--band-table", "the band table needs --poses or --model");
  }
  if (files && !args.bandTable.empty()) {
    throw UsageError("--band-table", "the band table goes with --truth-dir");
  }
  if (files && args.sameFaces) {
    throw UsageError("--same-faces", "the same faces go with --truth-dir");
  }
  if (files && !args.csv.empty()) {
    throw UsageError("--csv", "the per-image table goes with --truth-dir");
  }
}

CommandReport runFolders(const R& args, const Scheme& scheme, const std::vector<int>& selected) {
  CommandReport output;
  output.notesToStderr = args.json;
  auto report = evaluatePointFolders(args.truthDir, args.predictionDirs, args.labels, scheme,
                                     selected, args.threshold, args.sameFaces);
  report.offFaceAbove = args.offFaceAbove;
  const std::vector<double> edges = parseBandEdges(args.yawBands);
  if (!args.poses.empty()) {
    addYawBands(report, yawsByStem(report, readPoseCsv(args.poses)), edges,
                "yaw from " + args.poses.string());
  } else if (!args.model.empty()) {
    addYawBands(report, yawsFromModel(report, loadModel(args.model), kDefaultVerticalFovDeg), edges,
                "yaw of " + args.model.string() + " fitted to the truth's points");
  } else if (!args.json) {
    output.text =
        "yaw bands: skipped (give --poses F.csv with columns image,yaw_deg, or --model M to fit "
        "the model to each truth)\n";
  }
  output.text += args.json ? formatPointFolderJson(report) : formatPointFolderText(report);
  std::ostringstream notes;
  if (!args.out.empty()) {
    writeTextAtomically(args.out, formatPointFolderJson(report));
    notes << "report: " << args.out.string() << '\n';
  }
  if (!args.bandTable.empty()) {
    writeTextAtomically(args.bandTable, formatYawBandMarkdown(report));
    notes << "band table: " << args.bandTable.string() << '\n';
  }
  if (!args.csv.empty()) {
    writeTextAtomically(args.csv, formatPointFolderCsv(report));
    notes << "per-image table: " << args.csv.string() << '\n';
  }
  if (args.roc) {
    const std::vector<ScoredFit> fits = scoredFitsFromSummaries(report);
    if (fits.empty()) {
      throw InputError(
          "--roc: no prediction folder has a summary.csv with confidences (write them with clm3d "
          "fit --images --out-dir)");
    }
    notes << formatConfidenceRoc(confidenceRoc(fits, args.wrongAbove))
          << formatThresholdCounts(
                 countsAt(fits, args.acceptAt, args.wrongAbove, EvalOptions{}.wrongAbove));
  }
  output.notes = notes.str();
  return output;
}

}  // namespace eval_points_request_detail

const std::vector<Option<EvalPointsRequest>>& evalPointsOptions() {
  static const std::vector<Option<EvalPointsRequest>> table =
      eval_points_request_detail::makeOptions();
  return table;
}

CommandReport runEvalPoints(const EvalPointsRequest& args) {
  eval_points_request_detail::checkCombination(args);
  const Scheme scheme = Scheme::byNameOrPath(args.scheme);
  std::vector<int> selected;
  if (!args.points.empty()) {
    try {
      selected = parsePointList(args.points, scheme);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("--points: ") + e.what());
    }
  }
  if (!args.truthDir.empty()) return eval_points_request_detail::runFolders(args, scheme, selected);
  const auto report = evaluatePointFiles(args.truth, args.predictions, args.labels, scheme,
                                         selected, args.threshold);
  CommandReport output(args.json ? formatPointReportJson(report) : formatPointReportText(report));
  output.notesToStderr = args.json;
  if (!args.out.empty()) {
    writeTextAtomically(args.out, formatPointReportJson(report));
    output.notes = "report: " + args.out.string() + '\n';
  }
  return output;
}

}  // namespace clm3d
