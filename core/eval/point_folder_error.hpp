// The error of thesis eq. 5.1 over folders of point files: a folder of true mark-ups (STEM.pts,
// 68 or 25 points) against one folder of predictions per method (STEM.pts, .ljson or .csv, e.g.
// what `clm3d fit --images --out-dir` writes), paired by file stem and scored per image with
// evaluatePointSet over the chosen points. `clm3d eval-points --truth-dir --pred-dir` reports it
// (docs/evaluation.md, "Folders of point files").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/eval/point_set_error.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

struct PointFolderMethod {
  std::string label;  // the folder's name unless given
  std::filesystem::path folder;
  // Per truth image (PointFolderReport::stems order): the prediction file and its score, nullopt
  // where the folder has no prediction for the image.
  std::vector<std::optional<std::filesystem::path>> files;
  std::vector<std::optional<PointSetError>> results;
  int images = 0;            // truth images
  int predicted = 0;         // of those, with a prediction
  int missing = 0;           // without one: failures, their points count as not found
  double meanError = 0.0;    // mean / median of the per-image errors (images with a prediction
  double medianError = 0.0;  // and at least one scored point); NaN if none
  int truePoints = 0;        // selected points present in the truths, over every truth image
  int foundPoints = 0;       // of those, predicted within the threshold
  double foundShare = 0.0;   // foundPoints / truePoints (missing predictions count as not found)
};

struct PointFolderReport {
  std::string schemeName;
  std::filesystem::path truthFolder;
  double threshold = 0.18;
  std::vector<int> selected;       // 0-based; empty = every point
  std::vector<std::string> stems;  // the truth images, sorted
  std::vector<int> truePoints;     // per image: selected points present in its truth
  std::vector<PointFolderMethod> methods;
};

// Truths are the folder's *.pts files (read for the scheme: a 68-point file is converted to
// thesis25); predictions are STEM.pts, STEM.ljson or STEM.csv in each prediction folder (the first
// that exists). labels: empty or one per folder. Throws InputError naming the folder or file: a
// folder missing or without a .pts truth, a truth without a usable normalisation pair, an
// unreadable prediction or one with the wrong point count, a label count that does not match.
PointFolderReport evaluatePointFolders(const std::filesystem::path& truthFolder,
                                       const std::vector<std::filesystem::path>& predictionFolders,
                                       const std::vector<std::string>& labels, const Scheme& scheme,
                                       const std::vector<int>& selected, double threshold = 0.18);

// A header line, then per method: "LABEL (FOLDER): mean error E, median M over P/N images;
// within T: F/S points (X%); missing predictions: K". Numbers locale-independent.
std::string formatPointFolderText(const PointFolderReport& report);
// {"format": "clm3d-point-folder-evaluation", "version": 1, "scheme", "truth_folder", "threshold",
// "points" (1-based), "images", "methods": [{"label", "folder", "predicted", "missing",
// "mean_error", "median_error", "true_points", "found_points", "found_share"}]}. NaN is null.
std::string formatPointFolderJson(const PointFolderReport& report);
// One row per image and method: "image,method,status,error,max_error,true_points,scored_points,
// found_points,inter_ocular,prediction" with status ok or missing (empty numbers when missing).
std::string formatPointFolderCsv(const PointFolderReport& report);

}  // namespace clm3d
