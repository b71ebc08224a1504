// clm3d eval-points: the error of thesis eq. 5.1 between point files of one image (a fit against a
// hand mark-up; 68-point files are converted to thesis25) over a chosen subset of the points,
// normalised by the true distance of the scheme's normalisation pair (docs/evaluation.md). With
// --truth-dir and --pred-dir, whole folders paired by file stem (core/eval/point_folder_error).
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/eval/confidence_roc.hpp"
#include "core/eval/point_folder_error.hpp"
#include "core/eval/point_set_error.hpp"
#include "core/eval/yaw_bands.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/model_file.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct EvalPointsArgs {
  fs::path truth;
  std::vector<fs::path> predictions;
  fs::path truthDir;
  std::vector<fs::path> predictionDirs;
  fs::path csv;
  std::vector<std::string> labels;
  std::string scheme = "thesis25";
  std::string points;
  double threshold = 0.18;
  bool json = false;
  fs::path out;
  bool roc = false;
  double wrongAbove = 0.15;
  fs::path poses;
  fs::path model;
  std::string yawBands = "0,30,60,90";
  fs::path bandTable;
};

void runEvalPoints(const EvalPointsArgs& args) {
  const bool files = !args.truth.empty() || !args.predictions.empty();
  const bool folders = !args.truthDir.empty() || !args.predictionDirs.empty();
  if (files == folders) {
    throw CLI::ValidationError("--truth/--truth-dir",
                               "give --truth A.pts --pred B.pts (one image) or --truth-dir DIR "
                               "--pred-dir DIR (folders paired by file stem)");
  }
  if (files && (args.truth.empty() || args.predictions.empty())) {
    throw CLI::ValidationError("--truth/--pred", "one image needs both --truth and --pred");
  }
  if (folders && (args.truthDir.empty() || args.predictionDirs.empty())) {
    throw CLI::ValidationError("--truth-dir/--pred-dir",
                               "folders need both --truth-dir and --pred-dir");
  }
  if (files && args.roc) {
    throw CLI::ValidationError("--roc", "the confidence ROC goes with --truth-dir");
  }
  if (files && (!args.poses.empty() || !args.model.empty())) {
    throw CLI::ValidationError("--poses", "the yaw-band table goes with --truth-dir");
  }
  if (folders && !args.bandTable.empty() && args.poses.empty() && args.model.empty()) {
    throw CLI::ValidationError("--band-table", "the band table needs --poses or --model");
  }
  if (files && !args.bandTable.empty()) {
    throw CLI::ValidationError("--band-table", "the band table goes with --truth-dir");
  }
  if (files && !args.csv.empty()) {
    throw CLI::ValidationError("--csv", "the per-image table goes with --truth-dir");
  }
  const Scheme scheme = Scheme::byNameOrPath(args.scheme);
  std::vector<int> selected;
  if (!args.points.empty()) {
    try {
      selected = parsePointList(args.points, scheme);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("--points: ") + e.what());
    }
  }
  if (!args.truthDir.empty()) {
    auto report = evaluatePointFolders(args.truthDir, args.predictionDirs, args.labels, scheme,
                                       selected, args.threshold);
    const std::vector<double> edges = parseBandEdges(args.yawBands);
    if (!args.poses.empty()) {
      addYawBands(report, yawsByStem(report, readPoseCsv(args.poses)), edges,
                  "yaw from " + args.poses.string());
    } else if (!args.model.empty()) {
      addYawBands(report, yawsFromModel(report, loadModel(args.model), kDefaultVerticalFovDeg),
                  edges, "yaw of " + args.model.string() + " fitted to the truth's points");
    } else if (!args.json) {
      std::cout << "yaw bands: skipped (give --poses F.csv with columns image,yaw_deg, or "
                   "--model M to fit the model to each truth)\n";
    }
    std::cout << (args.json ? formatPointFolderJson(report) : formatPointFolderText(report));
    auto& notes = args.json ? std::cerr : std::cout;
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
            "--roc: no prediction folder has a summary.csv with confidences (write "
            "them with clm3d fit --images --out-dir)");
      }
      notes << formatConfidenceRoc(confidenceRoc(fits, args.wrongAbove));
    }
    return;
  }
  const auto report = evaluatePointFiles(args.truth, args.predictions, args.labels, scheme,
                                         selected, args.threshold);
  std::cout << (args.json ? formatPointReportJson(report) : formatPointReportText(report));
  if (!args.out.empty()) {
    writeTextAtomically(args.out, formatPointReportJson(report));
    (args.json ? std::cerr : std::cout) << "report: " << args.out.string() << '\n';
  }
}

}  // namespace

void addEvalPointsCommand(CLI::App& root) {
  auto args = std::make_shared<EvalPointsArgs>();
  CLI::App* command = root.add_subcommand(
      "eval-points",
      "Compare point files of one image (e.g. a fit with a hand mark-up), or folders of them "
      "paired "
      "by file stem: error of thesis eq. 5.1 over chosen points, normalised by the true "
      "eye-centre distance");
  auto* truth = command->add_option(
      "--truth", args->truth,
      "True points (.pts, .ljson, .csv; a 68-point file is converted to thesis25)");
  auto* pred = command->add_option("--pred", args->predictions,
                                   "Predicted points (repeat to compare several)");
  auto* truthDir = command->add_option(
      "--truth-dir", args->truthDir,
      "Folder of true points STEM.pts, one per image, instead of --truth: the scheme's points, or "
      "for thesis25 68 (iBUG) or 21 (AFLW, invisible points \"-1 -1\") paired with its points; "
      "the face box is that of each file's own points");
  auto* predDir = command->add_option(
      "--pred-dir", args->predictionDirs,
      "Folder of predictions STEM.pts, .ljson or .csv (repeat to compare methods); an image "
      "without one counts as a failure");
  truth->excludes(truthDir);
  pred->excludes(predDir);
  command->add_option("--label", args->labels,
                      "Name of each prediction (one per --pred or --pred-dir)");
  command->add_option("--csv", args->csv,
                      "With --truth-dir: write one row per image and method to this CSV");
  command->add_option(
      "--points", args->points,
      "Points to score: 1-based numbers, ranges and ids, e.g. 1-18,22 (default: all)");
  command
      ->add_option("--scheme", args->scheme, "Landmark scheme: thesis25, ibug68 or a scheme JSON")
      ->default_val("thesis25");
  command->add_option("--threshold", args->threshold, "Error at which a point counts as found")
      ->default_val(0.18)
      ->check(CLI::Range(1e-6, 100.0));
  command->add_flag("--json", args->json, "Print the report as JSON instead of text");
  command->add_flag("--roc", args->roc,
                    "With --pred-dir folders written by clm3d fit --images: how well the fits' "
                    "confidence (their summary.csv) tells right fits from wrong ones");
  command
      ->add_option("--wrong-above", args->wrongAbove,
                   "For --roc: a fit whose error exceeds this is wrong")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 10.0));
  command->add_option("--poses", args->poses,
                      "With --truth-dir: CSV with columns image,yaw_deg (e.g. AFLW's index.csv); "
                      "adds the per-|yaw|-band table");
  command->add_option("--model", args->model,
                      "With --truth-dir and no --poses: each truth's yaw is that of this model "
                      "fitted to its points (the model's scheme must be --scheme)");
  command
      ->add_option("--yaw-bands", args->yawBands,
                   "Edges of the |yaw| bands in degrees, ascending, e.g. 0,45,90")
      ->capture_default_str();
  command->add_option("--band-table", args->bandTable,
                      "With --poses or --model: write the band table as Markdown, the methods "
                      "side by side (faces fitted and error / face box per |yaw| band)");
  command->add_option("--out", args->out, "Also write the JSON report to this file");
  command->callback([args] { runEvalPoints(*args); });
}

}  // namespace clm3d::cli
