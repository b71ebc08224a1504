// Searching from several starts around a detector's: the box places the mean shape only roughly
// (0.15 of the eye distance off on average on real photos, docs/initialisation.md), which is more
// than a search's capture range. Fitting from a small grid of moved and rescaled copies of the
// start and keeping the fit the optimiser is most confident in trades a few searches per detection
// for a start inside that range; on a tracked video it runs only on frames that were detected.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <vector>

#include "core/detect/face_detector.hpp"
#include "core/fit/fitter.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d {

struct StartSearchSettings {
  // Shifts of the start in the image plane on a (2 steps + 1)^2 grid, `shift` of the start's
  // projected eye distance apart. steps 0 searches from the start alone.
  int steps = 0;
  double shift = 0.15;
  // Each shifted start is also searched at these relative sizes (1 = as placed), e.g. {0.9, 1.1}.
  // Empty: the placed size only.
  std::vector<double> sizes;
  // The rest of the grid is searched only when the fit from the start itself has a probability
  // (FitResult::probability) below this: a fit the point check already trusts is not searched
  // eight more times. 0 = the whole grid always.
  double onlyBelow = 0.0;

  bool operator==(const StartSearchSettings&) const = default;
};

// `start` moved in the image plane by shareOfEyes (x right, y down) times its projected
// eye-centre distance, at the same depth.
FitState shiftedStart(const ClmModel& model, const Fitter& fitter, FitState start,
                      const Eigen::Vector2d& shareOfEyes);

// What is done to each search's fit before fits are compared (the point refiner's refineFit: its
// check's probability is then the probability compared). Empty: nothing.
using FitFinisher = std::function<void(FitResult&)>;

// Searches `image` from `start` and, unless that fit's probability reaches settings.onlyBelow, from
// every start of the grid, finishes every fit with `finish`, and returns the one with the highest
// probability (the first on ties, so steps 0 with no sizes is fitter.fit(image, start) finished).
// `searches`, when given, receives the number of searches made.
FitResult fitFromBestStart(Fitter& fitter, const ClmModel& model, const cv::Mat& image,
                           const FitState& start, const StartSearchSettings& settings,
                           int* searches = nullptr, const FitFinisher& finish = {});

// The views next to `fit`'s in yaw, at its pitch (-1 where there is none): [lower yaw, higher].
std::array<int, 2> neighbouringViews(const ClmModel& model, int view);

// Whether `fit` is searched again from the neighbouring views: its probability is below `below`,
// and, unless `all`, it is of a kind that compares views (comparesViews).
bool wantsViewSearch(const FitResult& fit, double below, bool all);

// A fit searched again from the views next to its own in yaw (neighbouringViews): from its state
// turned half-way to each neighbour's centre, in that view, each finished with `finish`. Returns
// the most probable fit (FitResult::probability), `fit` itself unless another beats it by
// `margin` and is `accepted` (when given; the tracker's judgement). A turned start that leaves the
// image is no candidate. A head turning past its view's range is caught by the next view (issue
// 26); the one probability (core/fit/fit_probability.hpp) is what makes a side view's fit
// comparable with a frontal one's. `searches`, when given, has the searches made added.
FitResult searchNeighbouringViews(Fitter& fitter, const ClmModel& model, const cv::Mat& image,
                                  const FitResult& fit, double margin,
                                  const FitFinisher& finish = {},
                                  const std::function<bool(const FitResult&)>& accepted = {},
                                  int* searches = nullptr);

// A detected image's search over its faces: fitFromBestStart from stateFromBox of each face in
// `faces` order (best first), `placed` applied to each start when given, until `accepted` says
// yes to a fit or maxFaces faces are searched; returns the accepted fit, or without one the most
// probable (the first on ties); in `tried`, the number of faces searched, and `searches`, when
// given, has the searches made added. A false detection ranked first then costs one more search
// instead of the face. With search.placement TurnedFace, only the profile boxes are searched, each
// from its second placement (turnedFaceCalibration: where real turned faces sit in such a box).
// `clm3d fit`, `clm3d batch` (through fitFromDetections) and the tracker's detections all search
// their faces with it. A face whose start puts it outside the image is passed over. Throws
// InputError for an empty `faces`, a box stateFromBox refuses, or when no face could be searched
// (the first face's error). Where a face box puts its start: by the detector's calibration
// (boxCalibration), or, for the cascade's profile boxes only (the others are passed over), where
// real turned faces sit in such a box (turnedFaceCalibration).
enum class BoxPlacement { Calibrated, TurnedFace };

struct FaceSearch {
  int maxFaces = 1;
  StartSearchSettings starts;
  // The start grid's steps for a profile box's start (FaceBox::profile: a turned face, whose box
  // places its start less surely); -1: starts.steps, as for frontal boxes.
  int profileSteps = -1;
  std::function<bool(const FitResult&)> accepted;  // empty: the first face's fit is kept
  std::function<FitState(const FitState&)> placed;
  FitFinisher finish;
  // fitFromDetections: turns of the image searched while no fit is accepted (TrackerSettings::
  // tiltSteps and tiltStepDeg); 0 = upright only.
  int tiltSteps = 0;
  double tiltStepDeg = 15.0;
  // fitFromDetections: a kept fit whose probability is below widerBelow is searched again from the
  // starts of `wider` around its own state (moved and rescaled copies: a face the detector boxed
  // too small or too large), and the more probable fit kept. 0 = never.
  double widerBelow = 0.0;
  StartSearchSettings wider{1, 0.15, {0.8, 1.25}};
  // fitFromDetections: a kept fit that wantsViewSearch(fit, viewsBelow, viewsOfAll) is
  // searched again from the neighbouring views (searchNeighbouringViews) and the most probable
  // kept. 0 = never.
  double viewsBelow = 0.0;
  bool viewsOfAll = false;
  double viewMargin = 0.02;
  // fitFromDetections: while no fit is accepted after the upright faces and the tilted copies,
  // the upright profile boxes are searched from their second placement (BoxPlacement::TurnedFace).
  bool turnedPlacements = false;
  // fitFromBestFace: how each box places its start.
  BoxPlacement placement = BoxPlacement::Calibrated;
};
FitResult fitFromBestFace(Fitter& fitter, const ClmModel& model, const cv::Mat& image,
                          const std::vector<FaceBox>& faces, const FaceSearch& search,
                          int* tried = nullptr, int* searches = nullptr);

// The turns of a tilted-face search, nearest first: -step, +step, -2 step, +2 step, ...
std::vector<double> tiltAngles(int steps, double stepDeg);

// A still image's whole face search: fitFromBestFace over `faces` (the detector's upright boxes,
// possibly none); then, while no fit is accepted (search.accepted; without it, only when `faces`
// is empty), over detector.detectTurned(image, angle) for each of tiltAngles(search.tiltSteps,
// search.tiltStepDeg) that finds a face; then, when the most probable fit's probability is below
// search.widerBelow (after, with search.turnedPlacements while none is accepted, the upright
// profile boxes from their second placement), fitFromBestStart from its state with search.wider;
// then, below
// search.viewsBelow, searchNeighbouringViews. Returns the most probable fit, nullopt when no face
// was found upright or turned. `detectMilliseconds`, when given, has the turned detections' time
// added.
std::optional<FitResult> fitFromDetections(Fitter& fitter, const ClmModel& model,
                                           const cv::Mat& image, FaceDetector& detector,
                                           const std::vector<FaceBox>& faces,
                                           const FaceSearch& search,
                                           double* detectMilliseconds = nullptr);

}  // namespace clm3d
