// Where a search starts when there is no previous frame: the mean shape placed in a face
// detector's box (with the box-to-face relation calibrated per detector on renders and photos,
// docs/initialisation.md), or the pose and shape that best reproduce given 2D points (a
// `--init F.pts` file, a frame corrected by hand in the GUI). Both give a FitState the Fitter
// searches from; its depth Tz is the one the fit keeps.
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <vector>

#include "core/common/error.hpp"
#include "core/detect/face_detector.hpp"
#include "core/fit/fit_state.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d {

// The detector found no face. Callers that know the file compose "no face found in FILE".
class NoFaceFound : public InputError {
 public:
  using InputError::InputError;
};

// How a detector's box relates to the face in it, measured on renders of known pose (see
// boxCalibration in initialisation.cpp for the figures and how they were measured).
struct BoxCalibration {
  double iodPerWidth = 0.4;  // the face's frontal eye-centre distance / box width
  double eyeOffsetX = 0.0;   // (eye midpoint - box centre).x / box width (negated for mirrored)
  double eyeOffsetY = 0.0;   // (eye midpoint - box centre).y / box width (y down)
  double yawDeg = 0.0;       // |yaw| of the start; mirrored boxes turn positive, others negative
};

// The calibration of the detector's frontal or profile boxes.
BoxCalibration boxCalibration(DetectorKind detector, bool profile);

// A second placement of a profile box, tried when no fit from the first is accepted: measured on
// real turned faces (AFLW), where the first (boxCalibration, measured on renders, which profile
// boxes on near-frontal photos also suit) puts a real profile too small and too high in the box.
// nullopt for a frontal box and for detectors without one.
std::optional<BoxCalibration> turnedFaceCalibration(const FaceBox& box);

// The mean shape posed to fill the box: depth from the calibrated eye distance, the eye midpoint
// at its calibrated place in the box, yaw 0 for frontal boxes and the calibrated profile yaw for
// profile boxes (positive for mirrored ones), pitch 0 and the box's rollDeg (the calibrated eye
// offset turned with it). The planar 2D model keeps yaw 0 and
// takes the profile face's foreshortened size. Throws InputError for an empty or non-finite box.
FitState stateFromBox(const ClmModel& model, const Camera& camera, const FaceBox& box);
// The same with a given calibration instead of boxCalibration(box.detector, box.profile) (to
// compare calibrations: `clm3d detect --start-error`).
FitState stateFromBox(const ClmModel& model, const Camera& camera, const FaceBox& box,
                      const BoxCalibration& calibration);

struct PointsFitSettings {
  // Error of the given points (pixels) the shape prior is weighted for (weight = its square). Kept
  // small so that the points are trusted and the prior decides only what they leave open (missing
  // points, modes that move points in depth only): exact points are reproduced to ~0.01 pixel.
  double pointSigmaPixels = 0.25;
  int maxIterations = 60;  // Levenberg-Marquardt iterations per starting yaw
};

// The pose and shape whose projection best matches `points` (2 x the scheme's landmark count,
// input pixels) on the landmarks marked in `present` (empty = all): a similarity alignment of the
// rotated mean shape for each of a few starting yaws, then Levenberg-Marquardt on the reprojection
// error with the shape prior b_k^2 / variance_k, keeping the best. For the 3D model the depth Tz
// is estimated too (a weak prior keeps the scale near 1 where perspective does not tell); for the
// planar 2D model pitch and yaw stay 0 and Tz is the depth at which the scale is 1. Throws
// InputError for fewer than 4 present points, non-finite present points or wrong sizes.
FitState stateFromPoints(const ClmModel& model, const Camera& camera,
                         const Eigen::Matrix2Xd& points, const std::vector<bool>& present,
                         const PointsFitSettings& settings = {});

// The same from `start` alone (no other starting yaws), keeping its depth Tz as a search does:
// the state nearest a known one that reproduces `points`. The tracker carries a frame's checked,
// refined points on to the next frame this way, so the 3D state it starts from agrees with the
// points it output. Throws InputError as stateFromPoints does, and for a start whose shape has the
// wrong size.
FitState stateNearPoints(const ClmModel& model, const Camera& camera,
                         const Eigen::Matrix2Xd& points, const std::vector<bool>& present,
                         const FitState& start, const PointsFitSettings& settings = {});

// The settings of stateNearPoints from a search's own state, which is near already (the tracker's
// carried state, a fit's outline placed on its refined points): a few Levenberg-Marquardt steps,
// not the 60 a start from nothing is allowed (each a Jacobian and a small solve, a few hundredths
// of a millisecond).
inline PointsFitSettings nearbyPointsFit() {
  PointsFitSettings settings;
  settings.maxIterations = 10;
  return settings;
}

// Every landmark of `state` projected to input pixels (2 x the scheme's landmark count).
Eigen::Matrix2Xd projectState(const ClmModel& model, const Camera& camera, const FitState& state);

// Detects faces in `image` and returns stateFromBox of the best one (FaceDetector::detect's
// order). Throws NoFaceFound when there is none, InputError when the image's size is not the
// camera's.
FitState initialiseFromImage(const ClmModel& model, const Camera& camera, const cv::Mat& image,
                             FaceDetector& detector);

}  // namespace clm3d
