// The error of thesis eq. 5.1 between two point files of one image (a fit against a hand mark-up),
// over a chosen subset of the scheme's points: a fitted photo has no tracks CSV, and a 68-point
// mark-up converted to thesis25 only matches some of the model's points (docs/evaluation.md,
// "Point files"). Normalised by the true distance of the scheme's normalisation pair.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

// Parses a list of scheme points: comma-separated items, each a 1-based point number (as the
// thesis numbers its points), an inclusive range "a-b" of them, or a point id ("nose_tip").
// Returns sorted, distinct 0-based indices. Throws std::invalid_argument naming the bad item
// (unknown id, number out of 1..scheme size, reversed range, empty list).
std::vector<int> parsePointList(std::string_view text, const Scheme& scheme);

struct PointSetError {
  std::string label;         // a name for reports (the prediction's file by default)
  double interOcular = 0.0;  // true distance of the normalisation pair, pixels
  int selected = 0;          // points asked for
  int truePoints = 0;        // of those, present in the truth
  int scoredPoints = 0;      // ... and in the prediction
  int foundPoints = 0;       // ... with normalised error <= threshold
  double error = 0.0;        // mean normalised error over the scored points; NaN if none
  double maxError = 0.0;     // largest normalised point error; NaN if none
  // The face box: sqrt(w * h) of the axis-aligned bounding box of every point present in the
  // truth (all of the scheme's present points, not only the selected ones), pixels; NaN if the
  // truth has fewer than 2 present points or the box has no area.
  double boxSize = 0.0;
  // Mean pixel error over the scored points divided by boxSize: the normalisation used at large
  // pose, where the eye distance shrinks as the head turns; NaN if no point is scored.
  double boxError = 0.0;
  // Per scheme point: the normalised error, NaN where not selected or missing in either set.
  std::vector<double> pointErrors;
};

// Compares prediction with truth (both in the scheme's order and size) over the selected points
// (0-based; empty = every point). The normalisation pair need not be selected, but must be present
// and apart in the truth: otherwise std::invalid_argument. Also the box-normalised error, over the
// box of the truth's present points.
PointSetError evaluatePointSet(const LandmarkSet& truth, const LandmarkSet& prediction,
                               const Scheme& scheme, const std::vector<int>& selected,
                               double threshold = 0.18);

// The same with the face box given (that of the truth file's own points, ScoredTruth::boxSize;
// NaN: none) and a truth that may lack its normalisation pair (a turned AFLW face whose far eye is
// not marked): then interOcular, error, maxError and pointErrors are NaN and no point is found,
// while boxError is still the mean pixel error over the box. std::invalid_argument for sets not
// of the scheme's size or a selected index out of range.
PointSetError scorePointSet(const LandmarkSet& truth, double boxSize, const LandmarkSet& prediction,
                            const Scheme& scheme, const std::vector<int>& selected,
                            double threshold = 0.18);

// Reads both files for the scheme (a 68-point file is converted to thesis25 when the scheme is
// thesis25: docs/landmarks.md) and evaluates them. InputError names the file at fault: unreadable,
// wrong point count, or (the truth) no usable normalisation pair.
PointSetError evaluatePointFiles(const std::filesystem::path& truth,
                                 const std::filesystem::path& prediction, const Scheme& scheme,
                                 const std::vector<int>& selected, double threshold = 0.18);

// One truth against one or more predictions, as `clm3d eval-points` reports it.
struct PointEvaluationReport {
  std::string schemeName;
  std::string truthSource;
  double threshold = 0.18;
  std::vector<int> selected;  // 0-based; empty = every point
  std::vector<std::string> predictionSources;
  std::vector<PointSetError> results;  // one per prediction
};

// labels: empty, or one per prediction (default: the file name).
PointEvaluationReport evaluatePointFiles(const std::filesystem::path& truth,
                                         const std::vector<std::filesystem::path>& predictions,
                                         const std::vector<std::string>& labels,
                                         const Scheme& scheme, const std::vector<int>& selected,
                                         double threshold = 0.18);

// A line per prediction: "LABEL (FILE): error E over S/N points, max M, within T: F/S; eye
// distance D px". Numbers locale-independent.
std::string formatPointReportText(const PointEvaluationReport& report);
// {"format": "clm3d-point-evaluation", "version": 1, "scheme", "truth", "threshold", "points"
// (1-based), "predictions": [{"label", "file", "error", "max_error", "inter_ocular", "selected",
// "true_points", "scored_points", "found_points", "point_errors" (per scheme point, null where
// not scored)}]}. NaN is null.
std::string formatPointReportJson(const PointEvaluationReport& report);

}  // namespace clm3d
