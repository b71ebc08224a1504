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
  // The camera of every image or frame (`--fov`): a pinhole with this vertical field of view.
  double verticalFovDeg = kDefaultVerticalFovDeg;
  DetectorKind detector = DetectorKind::Cascade;
  // Where a detected face is searched from: the detector's start and a grid of moved copies, the
  // most confident fit kept (core/detect/start_search.hpp). One step of 0.10 eye distances (9
  // starts) was chosen on 100 LFPW training photos held out of the model: mean error from the
  // detector 0.076 -> 0.070 (fastncc), 0.097 -> 0.087 (rlms); steps of 0.15 or 0.20, two steps, and
  // rescaled starts did no better (docs/initialisation.md). Used by `clm3d fit` and by the tracker
  // on the frames it detects. The grid is searched only when the start's own fit has a confidence
  // below 0.9999 (for a model trained with photos, the point check's probability, which is above
  // that for about three photos in four): on the 100 held-out photos the median fit went from 35-40
  // to 11.7 ms and the mean error from 0.0426 to 0.0430 (docs/real-faces.md#time-a-photo).
  StartSearchSettings startSearch{1, 0.10, {}, 0.9999};
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
  // With a refiner that has a check (models trained with photos since format 5), a fit whose
  // check probability that its refined points are right is below this fails: a tracked frame is
  // lost (the tracker's confidence thresholds are then not applied), a photo's fit is rejected and
  // the next face searched.
  double minCheckProbability = 0.5;
  // With a model whose views are calibrated (ViewModel::calibration, models trained with photos
  // since format 7): a fit whose calibrated probability (FitResult::viewProbability) is below this
  // is also searched from the neighbouring views, and the most probable kept, in `clm3d track` and
  // `clm3d fit` alike (searchNeighbouringViews). The calibration puts a side view's score and a
  // frontal one's on one scale, which the raw responses are not. 0, the default, switches it off:
  // with the real-faces model trained with --calibrate-views (side views' ROC areas 0.64-0.78), the
  // search at 0.9 took the error over the face box on 5 LFPW photos turned -80..80 degrees from
  // 0.035 to 0.045 at |yaw| 0-30 and from 0.058 to 0.068 at 30-60
  // (docs/fitting.md#views-on-one-scale).
  double viewSearchProbability = 0.0;
  double viewSearchMargin = 0.02;  // on any of the scales (the tracker's too)

  // --- Read by a still image's fit only ---------------------------------------------------------
  // Tilted faces: when no upright face's fit passes the point refiner's check (or no face is
  // found), the detector runs on copies of the image turned by +-tiltStepDeg, +-2 tiltStepDeg, ...
  // (tiltSteps each way, nearest first) and searches their faces from starts tilted with them,
  // until a fit passes (FaceDetector::detectTurned). The detectors find faces within about 15
  // degrees of upright. 0 = off.
  int tiltSteps = 2;
  double tiltStepDeg = FaceSearch{}.tiltStepDeg;
  // Unsure fits: when the kept fit's check probability is below this, it is searched again from
  // the grid of widerSearch around it (moved and rescaled copies of it), and the more confident fit
  // kept (FaceSearch::widerBelow): a face the detector boxed too small or too large. On 100 LFPW
  // training photos held out of the model, with every detector start rescaled by 1.3 or 1 / 1.3,
  // the mean error went from 0.069 to 0.054 at 0.97 (0.059 at 0.9); from the detector's own
  // starts, 0.0458 to 0.0456 (docs/real-faces.md). 0 = never.
  double widerSearchBelow = 0.97;
  StartSearchSettings widerSearch = FaceSearch{}.wider;
  // The kept fit's points are refined this many times, from themselves and from copies moved
  // around them, and the runs averaged (RefinerStarts; about 1 ms a run). The tracker refines once.
  int refineRuns = 9;
  // How far those copies are moved, in eye distances (RefinerStarts::spread).
  double refineSpread = RefinerStarts{}.spread;
  // Those runs are made only when the kept fit's check probability is below this: a fit the check
  // doubts. With the start grid's 0.9999 on the 100 held-out photos: median fit 11.7 -> 3.5-4.2 ms,
  // mean error 0.0430 -> 0.0429 (docs/real-faces.md#time-a-photo). 0 = always.
  double refineRunsBelow = 0.9999;

  bool operator==(const FaceSearchSettings&) const = default;
};

}  // namespace clm3d
