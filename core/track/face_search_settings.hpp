// How a face is found and fitted in one image: the settings a still image's fit (`clm3d fit`,
// `clm3d batch`, the studio's photo fit: ImageFitSettings) and the tracker (TrackerSettings) have
// in common. Both derive from this struct, so each of these settings has one field and one default,
// and a photo fit's settings are taken from the options a user gave without copying them field by
// field (issue 28). The options table (core/track/tracker_options) reads and writes them; its
// scopes say which command reads which: the tracker reads the first group, a still image's fit
// every field.
#pragma once

#include <vector>

#include "core/detect/face_detector.hpp"
#include "core/detect/start_search.hpp"
#include "core/fit/fitter.hpp"
#include "core/geometry/camera.hpp"
#include "core/refine/descent_refinement.hpp"

namespace clm3d {

struct FaceSearchSettings {
  // --- Read by both ---------------------------------------------------------------------------
  FitSettings fit;
  // The camera of every image or frame (`--fov`): a pinhole with this vertical field of view; 0:
  // the input's default (stillImageFovDeg, videoFovDeg).
  double verticalFovDeg = 0.0;
  DetectorKind detector = DetectorKind::Cascade;
  // Where a detected face is searched from: the detector's start and a grid of moved copies, the
  // most confident fit kept (core/detect/start_search.hpp). One step of 0.10 eye distances (9
  // starts) was chosen on 100 LFPW training photos held out of the model: mean error from the
  // detector 0.076 -> 0.070 (fastncc), 0.097 -> 0.087 (rlms); steps of 0.15 or 0.20, two steps, and
  // rescaled starts did no better (docs/initialisation.md). Used by `clm3d fit` and by the tracker
  // on the frames it detects. The grid is searched only when the start's own fit has a probability
  // below 0.996 (a photo's: its photo-fit probability on a calibrated model, where 0.996 at |yaw| 0
  // is the check's 0.9999 of the real-face model's curve; else the point check's, above 0.9999 for
  // about three photos in four): on the 100 held-out photos the median fit went from 35-40 to 11.7
  // ms and the mean error from 0.0426 to 0.0430 at the check's 0.9999
  // (docs/real-faces.md#time-a-photo).
  StartSearchSettings startSearch{1, 0.10, {}, 0.996};
  // The detector's faces searched, best first, until one's fit does not fail: a false detection
  // ranked first (a mouth, a pattern on a shirt) or a second person no longer costs the face. On
  // the LFPW photo sequences a frame of image_0016 was lost to the other person's box
  // (docs/initialisation.md). One face loop for both (fitFromBestFace): the tracker judges each fit
  // as it judges a frame, `clm3d fit` by the point refiner's check (without a check, whose
  // confidence would tell a wrong fit, it searches the best face only); the first fit that passes
  // is kept, or else the most confident. 1 = the best face only.
  int facesTried = 3;
  // Apply the model's point refiner (ClmModel::refiner, learnt from annotated photos; models
  // without photos have none) to every search's points (core/refine/refined_fit.hpp). A tracked
  // frame still starts the next from the fitted 3D state.
  bool refine = true;
  // A fit whose probability of being right (FitResult::probability, core/fit/fit_probability.hpp:
  // the point refiner's check for models trained with photos, else the search's score on its
  // calibration or built-in curve) is below this fails: a tracked frame is lost and the face
  // detected again, a photo's fit is rejected and the next face searched. One threshold for every
  // optimiser and view; with the built-in curves it fails what the NCC threshold of 0.35 and the
  // experts' of 0.45 failed before.
  double minProbability = 0.5;
  // A fit whose probability is below this is also searched from the neighbouring views in yaw
  // (half-way to their centres), and the most probable kept if it is more probable by
  // viewSearchMargin, in `clm3d track` and `clm3d fit` alike (searchNeighbouringViews): a head
  // turning past a view's range is caught by the next view before it is lost. With the built-in
  // curve it searches below the mean NCC of 0.7 the template optimisers searched below before.
  // 0 switches it off.
  double viewSearchBelow = 0.9;
  // Whether a fit whose probability does not compare views (comparesViews: the point refiner's
  // check's, models trained with photos; the experts' response on the built-in curve, rlms on
  // models without calibrations) is searched from the neighbouring views too. Off, so that
  // neither searches, as rlms did not before there was one probability: on the 5 LFPW photos
  // turned -80..80 degrees of docs/real-faces.md the search on checked fits took the frames
  // reported as tracked with an error above 0.3 eye distances from 59 to 73 (of 352 and 358
  // tracked); franck.mp4, the 25 photo sequences and the LFPW photos were unchanged. On franck.mp4
  // a search comparing the experts' raw responses walked the fit into +-60 degree views.
  bool viewSearchAll = false;
  double viewSearchMargin = 0.02;

  // --- Read by a still image's fit only ---------------------------------------------------------
  // The start grid's steps for a start from a profile box (FaceSearch::profileSteps): a turned
  // face's box places its start less surely, and the photo search now ranks turned fits on the
  // calibrated probability. On the 1,200 AFLW test faces, faces fitted right per |yaw| band
  // 374 / 278 / 130 -> 373 / 289 / 143 at 2 (3: 372 / 297 / 145), fits off the face reported
  // 12 / 34 / 38 -> 13 / 36 / 41, the fit's median 35 -> 74 ms there (3: 130 ms); on LFPW, whose
  // faces the frontal cascade mostly boxes, mean error 0.0449 -> 0.0444
  // (docs/initialisation.md#profile-boxes-searched-wider).
  int profileStartSteps = 2;
  // Tilted faces: when no upright face's fit passes the point refiner's check (or no face is
  // found), the detector runs on copies of the image turned by +-tiltStepDeg, +-2 tiltStepDeg, ...
  // (tiltSteps each way, nearest first) and searches their faces from starts tilted with them,
  // until a fit passes (FaceDetector::detectTurned). The detectors find faces within about 15
  // degrees of upright. 0 = off.
  int tiltSteps = 2;
  double tiltStepDeg = FaceSearch{}.tiltStepDeg;
  // Profile boxes placed again: while no fit passes after the upright faces and the tilted
  // copies, the upright profile boxes are searched from their second placement, where real turned
  // faces sit in such a box (turnedFaceCalibration, core/detect/initialisation.hpp;
  // FaceSearch::turnedPlacements). On the 1,200 AFLW test faces, faces fitted right (error under
  // 0.08 of the face box) per |yaw| band 362 / 220 / 63 -> 362 / 243 / 109, the 224 LFPW test
  // photos unchanged (docs/initialisation.md#profile-boxes-placed-as-real-turned-faces).
  bool turnedPlacements = true;
  // Unsure fits: when the kept fit's probability is below this, it is searched again from the
  // grid of widerSearch around it (moved and rescaled copies of it), and the more probable fit
  // kept (FaceSearch::widerBelow): a face the detector boxed too small or too large. On 100 LFPW
  // training photos held out of the model, with every detector start rescaled by 1.3 or 1 / 1.3,
  // the mean error went from 0.069 to 0.054 at the check's 0.97 (0.059 at 0.9); from the
  // detector's own starts, 0.0458 to 0.0456 (docs/real-faces.md). A calibrated model's photo fits
  // compare their photo-fit probability, where 0.62 at |yaw| 0 is the check's 0.97
  // (docs/fitting.md#one-probability-through-the-photo-search). 0 = never.
  double widerSearchBelow = 0.62;
  StartSearchSettings widerSearch = FaceSearch{}.wider;
  // The kept fit's points are refined this many times, from themselves and from copies moved
  // around them, and the runs averaged (RefinerStarts; about 1 ms a run). The tracker refines once.
  int refineRuns = 9;
  // How far those copies are moved, in eye distances (RefinerStarts::spread).
  double refineSpread = RefinerStarts{}.spread;
  // Those runs are made only when the kept fit's check probability is below this: a fit the check
  // doubts. With the start grid's 0.9999 on the 100 held-out photos: median fit 11.7 -> 3.5-4.2 ms,
  // mean error 0.0430 -> 0.0429 (docs/real-faces.md#time-a-photo); 0.996 on a calibrated model's
  // photo-fit probability, as the start grid's. 0 = always.
  double refineRunsBelow = 0.996;

  bool operator==(const FaceSearchSettings&) const = default;
};

// The vertical field of view of the camera of a still image and of a video's frames: the one
// given, or kStillImageVerticalFovDeg and kDefaultVerticalFovDeg.
inline double stillImageFovDeg(const FaceSearchSettings& settings) {
  return settings.verticalFovDeg > 0.0 ? settings.verticalFovDeg : kStillImageVerticalFovDeg;
}
inline double videoFovDeg(const FaceSearchSettings& settings) {
  return settings.verticalFovDeg > 0.0 ? settings.verticalFovDeg : kDefaultVerticalFovDeg;
}

}  // namespace clm3d
