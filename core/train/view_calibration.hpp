// Putting the views on one scale (issue 26): the patch experts of different views do not respond
// on one scale (a side view's right fit scores about what a frontal view's wrong one does), so a
// fit cannot choose its view by the score, and a fit in a view the point refiner never learnt
// (profiles) has nothing to be judged on. Here each view gets a logistic curve from the search's
// confidence to the probability that the search is right (ViewModel::calibration), fitted on
// annotated faces the experts did not learn from (photos their source's `per_view` cap left out),
// each searched from starts near its truth and from wrong ones (moved, turned a view away), as a
// tracker or a start grid would meet them. From the same searches each view learns its own check
// (ViewModel::check, core/model/view_check.hpp): the response does not order a side view's right
// fits above its wrong ones, the gradient features at the view's visible points do. It also marks
// the views the point refiner learnt (ViewModel::refined) from where its photos sat.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/dataset/training_photos.hpp"
#include "core/model/clm_model.hpp"
#include "core/train/photo_samples.hpp"

namespace clm3d {

struct ViewCalibrationSettings {
  // Faces searched per calibrated view (a view and its mirror image count as one): the held-out
  // ones first, then, where there are too few, faces the experts learnt from.
  // 150: the views' checks learn from about 300-700 searches each (60 gave them too few).
  int facesPerView = 150;
  // A search is right when its mean error over the face's trusted points is below this share of
  // their box (sqrt(w h)); the check's line of 0.15 eye distances is about 0.07 of a frontal box.
  double rightBelow = 0.08;
  // The wrong starts: the truth moved by this share of its eye distance, and turned by this much
  // yaw (to the side with a view), in the view nearest the turned pose.
  double shiftEyes = 0.5;
  double turnDeg = 30.0;
  // A view with fewer right or wrong searches than this takes the curve of the views at its yaw
  // (every pitch), or of all views.
  int minPerClass = 10;
  // A view is marked as learnt by the refiner when at least this share of the refiner's faces
  // (photo and mirror image) sit in it (nearest view of their fitted pose). 0 marks every view
  // learnt, the default: with views marked unlearnt (0.02), the LFPW-trained model's fits in the
  // pitched and +-60 views were judged on their calibration alone, and on 5 LFPW photos turned
  // -80..80 degrees the error over the face box at |yaw| 30-60 went from 0.058 to 0.121
  // (docs/fitting.md#views-on-one-scale).
  double refinerShare = 0.0;
  // Each view's own check (ViewModel::check): the ridge of its linear score, every how many faces
  // one is kept out to fit its curve and measure it, and the fewest right and wrong searches a
  // view must have to learn one (a quarter as many among the kept-out faces).
  double checkRidge = 0.2;
  int checkCalibrationEvery = 5;
  int minCheckPerClass = 20;
  std::uint64_t seed = 1;
  int threads = 0;
};

struct ViewCalibrationRow {  // one calibrated view, for the training report
  int view = 0;              // the view (its mirror image shares the row)
  int heldOut = 0;           // faces the experts did not learn from
  int learnt = 0;            // faces they did (used where there were too few held out)
  int right = 0, wrong = 0;  // searches that ended in this view
  LogisticCurve curve;
  // How well the response tells this view's right searches from its wrong ones: the share of
  // (right, wrong) pairs in which the right one scores higher (the ROC's area; 0.5 = not at all).
  double separation = 0.5;
  bool pooled = false;  // too few searches: the curve is that of its yaw, or of all views
  int refinerFaces = 0;
  // The view's check, measured on the searches of the faces it did not learn from (`checked`;
  // 0: the view has no check): its ROC area and that of the response on the same searches.
  int checked = 0;
  double checkSeparation = 0.5;
  double heldOutResponseSeparation = 0.5;
};

// Sets every view's calibration and `refined` in `model` (trained: shape, views with experts)
// from `photos` and where each went (`placements`, as preparePhotoSamples gives them, in photo
// order). Nothing changes when no photo is usable or the views have no experts. Deterministic
// for a seed whatever the thread count; Cancelled when `cancel` fires.
std::vector<ViewCalibrationRow> calibrateViews(ClmModel& model,
                                               const std::vector<TrainingPhoto>& photos,
                                               const std::vector<PhotoPlacement>& placements,
                                               const ViewCalibrationSettings& settings,
                                               const ProgressCallback& progress = {},
                                               const CancelToken* cancel = nullptr);

// The rows as a table for a person: per calibrated view its centre, faces, searches right and
// wrong, the curve's probability at three expert responses, and whether the refiner learnt it.
std::string formatViewCalibration(const ClmModel& model,
                                  const std::vector<ViewCalibrationRow>& rows);

}  // namespace clm3d
