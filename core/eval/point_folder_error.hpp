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
#include "core/scheme/landmark_set.hpp"
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
  double meanBoxError =
      0.0;  // mean of the per-image errors / face box (PointSetError); NaN if none
  // Per truth image: the folder's summary.csv (clm3d fit --images) has status "rejected" for it.
  // Such an image is not fitted in the yaw-band table even when its points were kept.
  std::vector<bool> rejected;
  // With yaw bands: one row per band (PointFolderReport::bandEdges).
  struct Band {
    int faces = 0;                // truth images whose |yaw| falls in the band
    int fitted = 0;               // of those, with a prediction that was not rejected
    double meanBoxError = 0.0;    // over the fitted faces with a scored point; NaN if none
    double medianBoxError = 0.0;  // the median of the same
    // Normalised by the eye distance, over the fitted faces whose truth has both eye centres.
    double meanEyeError = 0.0;
    int truePoints = 0;       // selected points present in the band's truths
    int foundPoints = 0;      // of those, fitted and within the threshold
    double foundShare = 0.0;  // foundPoints / truePoints (unfitted faces count as not found)
    // Of the fitted faces, those whose error over the face box exceeds the report's offFaceAbove:
    // fits reported although they are off the face.
    int offFace = 0;
  };
  std::vector<Band> bands;
};

struct PointFolderReport {
  std::string schemeName;
  std::filesystem::path truthFolder;
  double threshold = 0.18;
  std::vector<int> selected;       // 0-based; empty = every point
  std::vector<std::string> stems;  // the truth images, sorted
  // Per image: selected points present in its truth, 0 for a truth without its normalisation pair
  // (those are scored by the face box only and left out of the shares within the threshold).
  std::vector<int> truePoints;
  std::vector<LandmarkSet> truths;  // per image, as read for the scheme (invisible points missing)
  std::vector<bool> eyeNormalised;  // per image: the truth has its normalisation pair, apart
  std::vector<std::string> truthSchemes;  // per image: the truth file's scheme (ScoredTruth)
  std::vector<PointFolderMethod> methods;
  // Yaw bands (core/eval/yaw_bands.hpp): per image the truth's yaw in degrees (NaN: unknown, in no
  // band), the |yaw| edges (bands [e0,e1), [e1,e2), ... the last closed) and where the yaws came
  // from. Empty when there is no band table.
  std::vector<double> yawDeg;
  std::vector<double> bandEdges;
  std::string yawSource;
  // With sameFaces, only the truth images every method fitted are scored (a prediction file that
  // its folder's summary.csv does not mark rejected), so that methods that fit different faces
  // are compared on the same ones; notFittedByAll counts the images left out.
  bool sameFaces = false;
  int notFittedByAll = 0;
  // The error over the face box above which a fitted face counts as off the face in the bands
  // (0.08: the line the views' checks learn right from wrong by, docs/training.md).
  double offFaceAbove = 0.08;
};

// Truths are the folder's *.pts files, read with readScoredTruth
// (core/eval/detail/scored_truth.hpp: for thesis25 a 68-point file is converted and AFLW's 21
// points are paired; a point written "-1 -1", AFLW's mark of an invisible point, is missing, in the
// truths and in .pts predictions; the face box is that of the file's own points); predictions are
// STEM.pts, STEM.ljson or STEM.csv in each prediction folder (the first that exists). A truth
// without its normalisation pair (a profile whose far eye is not marked) is scored by the face box
// only. labels: empty or one per folder. Throws InputError naming the folder or file: a folder
// missing or without a .pts truth, a truth the scheme cannot be paired with, an unreadable
// prediction or one with the wrong point count, a label count that does not match.
PointFolderReport evaluatePointFolders(const std::filesystem::path& truthFolder,
                                       const std::vector<std::filesystem::path>& predictionFolders,
                                       const std::vector<std::string>& labels, const Scheme& scheme,
                                       const std::vector<int>& selected, double threshold = 0.18,
                                       bool sameFaces = false);

// A header line, then per method: "LABEL (FOLDER): mean error E, median M over P/N images;
// within T: F/S points (X%); missing predictions: K". Numbers locale-independent.
std::string formatPointFolderText(const PointFolderReport& report);
// {"format": "clm3d-point-folder-evaluation", "version": 1, "scheme", "truth_folder", "threshold",
// "points" (1-based), "images", "methods": [{"label", "folder", "predicted", "missing",
// "mean_error", "median_error", "mean_box_error", "true_points", "found_points", "found_share"}]}
// and, with yaw bands, "yaw_source", "band_edges" and per method "bands": [{"min_abs_yaw",
// "max_abs_yaw", "faces", "fitted", "mean_box_error", "mean_error", "true_points",
// "found_points", "found_share"}]; with sameFaces, "not_fitted_by_all". NaN is null.
std::string formatPointFolderJson(const PointFolderReport& report);
// One row per image and method: "image,method,status,error,max_error,true_points,scored_points,
// found_points,inter_ocular,box_error,box_size,yaw_deg,prediction" with status ok, rejected or
// missing (empty numbers when missing; yaw_deg empty when unknown).
std::string formatPointFolderCsv(const PointFolderReport& report);

}  // namespace clm3d
