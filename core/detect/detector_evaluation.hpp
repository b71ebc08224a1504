// Face detectors measured on annotated photos (`clm3d detect`, docs/initialisation.md): per
// detector, how often the annotated face is found, how often the best box (the one
// initialiseFromImage starts from) is another face, how long detection takes; the box calibration
// (eye distance and eye midpoint in box widths) measured on the photos; and, with a model, the
// error of the mean shape placed in the annotated face's box by stateFromBox.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/common/progress.hpp"
#include "core/detect/face_detector.hpp"
#include "core/detect/initialisation.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/clm_model.hpp"
#include "core/scheme/landmark_set.hpp"

namespace clm3d {

// The annotated face of a truth landmark file: 68 iBUG points (converted to the thesis's 25) or 25
// thesis points, whose eye centres are thesis points 8 and 11 (the means of iBUG 36-41 and 42-47);
// or the points of another scheme (AFLW's 21, where a turned head hides an eye), whose face is
// the box around their visible points, and whose points, where a built-in scheme map takes them
// to thesis25, place the model's mean shape for the box calibration (`--calibrate-to mean-shape`).
struct TruthFace {
  LandmarkSet points;  // thesis25 order, 2D pixels (0-based); empty for a scheme without a map
  Eigen::Vector2d eyeMid = Eigen::Vector2d::Zero();
  double iod = 0.0;  // distance between the eye centres, pixels; 0 for another scheme
  // The box around the file's present points, pixels (AFLW's "-1 -1" invisible points left out).
  cv::Rect2d visibleBox;

  bool hasEyes() const { return iod > 0.0; }
  // The point a detector's box must hold to be this face: the eye midpoint, or for a truth of
  // another scheme the centre of visibleBox.
  Eigen::Vector2d anchor() const;
};

// Reads a truth file (.pts, .ljson, .csv). 68 or 25 points: the eye centres are needed. Any other
// count: at least 2 present points (a .pts point written "-1 -1", AFLW's mark of an invisible
// point, is missing). InputError naming the file when it cannot be read or lacks what is needed.
TruthFace readTruthFace(const std::filesystem::path& path);

// A named set of box calibrations, for the start error: the built-in one (boxCalibration) with
// some entries replaced, e.g. by a calibration measured with `clm3d detect --calibrate`.
struct CalibrationSet {
  std::string label = "built-in";
  std::map<std::pair<DetectorKind, bool>, BoxCalibration> overrides;  // (detector, profile)
  BoxCalibration get(DetectorKind detector, bool profile) const;
};

// The calibrations a `clm3d detect --calibrate --out F.json` report holds (frontal boxes of each
// detector; profile boxes when measured). InputError naming the file when it is not such a report.
CalibrationSet readCalibrationSet(const std::filesystem::path& path);

// What the box calibration is measured against (with a model).
enum class CalibrationTarget {
  // The truth's eye centres: the face's frontal eye distance (from the model's pose and shape
  // fitted to the truth) and the truth's eye midpoint (docs/initialisation.md's definition).
  Eyes,
  // The mean shape (shape coefficients 0, scale 1) fitted to the truth's startPoints by pose and
  // depth: the eye distance and eye midpoint that stateFromBox would have to give to place the
  // mean shape best. Differs from Eyes where the model's mean face is proportioned unlike the
  // photographed ones.
  MeanShape
};

struct DetectorEvaluationSettings {
  FaceDetectorSettings detector;
  CalibrationTarget calibrationTarget = CalibrationTarget::Eyes;
  double verticalFovDeg = kDefaultVerticalFovDeg;  // the camera of every photo (with a model)
  // Calibration: frontal boxes count on faces within this |yaw| of frontal (with a model, which
  // gives the yaw and the frontal eye distance; without one every frontal box counts, with the
  // image eye distance).
  double frontalYawDeg = 15.0;
  // Start error: the thesis points scored (0-based; thesis 1-18 and 22, those a 68-point mark-up
  // and the model define alike).
  std::vector<int> startPoints = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21};
};

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One photo seen by one detector.
struct ImageDetection {
  std::filesystem::path image;
  int boxes = 0;              // boxes the detector returned
  bool firstProfile = false;  // the best box is a profile box
  int annotated = -1;  // the box nearest the truth's eye midpoint, if it contains it; else -1
  FaceBox box;         // that box (valid when annotated >= 0)
  // The truth's eye midpoint - the box centre, in box widths (x negated for mirrored boxes).
  double offsetX = kNaN;
  double offsetY = kNaN;
  double milliseconds = 0.0;        // detect() wall time
  double iod = 0.0;                 // true eye distance, pixels (frontal one with a model)
  double yawDeg = kNaN;             // the truth's yaw (with a model)
  std::vector<double> startErrors;  // per calibration set (with a model and a found face)
  int band = -1;                    // its |yaw| band (addDetectionBands), -1: none

  bool found() const { return annotated >= 0; }
  bool noFace() const { return boxes == 0; }
  // The best box, which initialiseFromImage starts from, is not the annotated face.
  bool wrongFace() const { return boxes > 0 && annotated != 0; }
};

struct CalibrationEstimate {
  int faces = 0;                // boxes measured
  BoxCalibration median;        // medians of each figure (yawDeg: median |yaw|, with a model)
  double sdIodPerWidth = kNaN;  // standard deviations
  double sdEyeOffsetX = kNaN;
  double sdEyeOffsetY = kNaN;
};

struct StartErrorSummary {
  std::string calibration;  // the CalibrationSet's label
  int faces = 0;
  double mean = kNaN;
  double median = kNaN;
};

// One detector's counts over the images of one |yaw| band (addDetectionBands).
struct DetectionBand {
  std::string label;  // e.g. "60-90"
  int images = 0;
  int found = 0;
  int noFace = 0;
  int wrongFace = 0;
  int profileFirst = 0;  // images whose best box is a profile box
  double medianMilliseconds = kNaN;
};

struct DetectorEvaluation {
  DetectorKind detector = DetectorKind::Cascade;
  std::vector<ImageDetection> images;
  int found = 0;
  int noFace = 0;
  int wrongFace = 0;
  double medianMilliseconds = kNaN;
  double p90Milliseconds = kNaN;
  CalibrationEstimate frontal;  // frontal boxes on faces within frontalYawDeg
  CalibrationEstimate profile;  // profile boxes (x offsets of mirrored boxes negated)
  std::vector<StartErrorSummary> startErrors;  // per calibration set
  std::vector<DetectionBand> bands;            // per |yaw| band (addDetectionBands)
};

struct DetectorEvaluationReport {
  DetectorEvaluationSettings settings;
  bool withModel = false;
  std::vector<DetectorEvaluation> detectors;
  std::string bandSource;  // where the bands' yaws came from (e.g. the poses CSV)
};

// The truth file of each image: STEM.pts / .ljson / .csv in truthDir, or beside the image when
// truthDir is empty. InputError naming the image when it has none.
std::vector<std::filesystem::path> findTruthFiles(const std::vector<std::filesystem::path>& images,
                                                  const std::filesystem::path& truthDir);

// Runs each detector over every image (read once) and compares the boxes with the truth. With a
// model (thesis25 scheme), each truth also gives its yaw and frontal eye distance (stateFromPoints)
// and each found face the start error of stateFromBox under every calibration set (mean point
// distance over settings.startPoints / true eye distance). Progress per image; cancellable.
// InputError naming the file for an unreadable image or truth file.
DetectorEvaluationReport evaluateDetectors(const std::vector<std::filesystem::path>& images,
                                           const std::vector<std::filesystem::path>& truths,
                                           const std::vector<DetectorKind>& detectors,
                                           const DetectorEvaluationSettings& settings,
                                           const ClmModel* model = nullptr,
                                           const std::vector<CalibrationSet>& calibrations = {},
                                           const ProgressCallback& progress = {},
                                           const CancelToken* cancel = nullptr);

// Counts every detector's results per |yaw| band: bandOfImage holds each image's band index (in
// evaluateDetectors' order; -1: in no band), labels the bands' names. InputError when the counts
// do not match or an index is out of range.
void addDetectionBands(DetectorEvaluationReport& report, const std::vector<int>& bandOfImage,
                       const std::vector<std::string>& labels, const std::string& source);

// The report as a text table (calibration figures when withCalibration) and as JSON (readable by
// readCalibrationSet).
std::string formatDetectorEvaluationText(const DetectorEvaluationReport& report,
                                         bool withCalibration);
std::string formatDetectorEvaluationJson(const DetectorEvaluationReport& report,
                                         bool withCalibration);

}  // namespace clm3d
