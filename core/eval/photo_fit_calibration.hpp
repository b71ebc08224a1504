// The point refiner's check calibrated on photo fits (`clm3d calibrate`): the whole still-image
// pipeline (ImageFitter: detection, the face loop, tilted copies, search, refinement) fits
// annotated photos, and per |yaw| of the fitted view a logistic curve of the check's log-odds
// learns the probability that such a fit is right (PhotoFitCurve, core/model/descent_refiner.hpp).
// The check learns from refined starts around the truth of near-frontal photos; on the pipeline's
// fits of turned faces it is too sure (on 1,185 AFLW training faces it accepted 82 of the 179 fits
// off the face in the +-60 views, docs/fitting.md#calibrated-on-photo-fits-clm3d-calibrate). A fit
// is right when its mean error over the truth's points is at most `rightBelow` of the truth's face
// box (the line the AFLW bands count a fit off the face by, docs/real-faces.md). The photos should
// be ones the model did not learn from.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/model/clm_model.hpp"
#include "core/track/batch_fit.hpp"

namespace clm3d {

// `fit` with the photo search's effort thresholds (the start grid, the wider search, the refiner
// runs), which a calibrated model's photo fits read on their photo-fit probability, set to the
// point check's values the defaults stand for at |yaw| 0 (docs/fitting.md#one-probability-
// through-the-photo-search): 0.9999, 0.97 and 0.9999 for 0.996, 0.62 and 0.996. The calibration
// fits its photos with the model uncalibrated, whose fits carry the check's probability; so they
// are searched with the effort of the calibrated pipeline it learns to judge.
ImageFitSettings searchedAsCalibrated(ImageFitSettings fit);

struct PhotoFitCalibrationSettings {
  // The pipeline calibrated: clm3d fit's defaults, searched as the calibrated pipeline searches.
  ImageFitSettings fit = searchedAsCalibrated(ImageFitSettings{});
  double rightBelow = 0.08;  // error over the truth's face box
  // A |yaw| of views gets a curve from at least this many right and this many wrong fits; the
  // others take the curve of the nearest |yaw| that has one.
  int minEach = 10;
  // A |yaw| with at least this many fits gets a curve with an image term (PhotoFitCurve); 0:
  // curves of the check alone (model format 9's).
  int imageMinFits = 100;
  int threads = 0;  // 0: one per core
};

// One |yaw| of views: its fits and what a threshold of fit.minProbability does to them with the
// check's own probability and with the curves. "held out": each fit judged by the curves learnt
// from the other half of the photos (even and odd positions in the list), so that the figures say
// what the curves do on photos they did not learn from.
struct PhotoFitCalibrationRow {
  double viewYawDeg = 0.0;
  int right = 0, wrong = 0;
  bool curve = false;  // this |yaw| has its own curve
  int rightKeptBefore = 0, wrongAcceptedBefore = 0;
  int rightKeptHeldOut = 0, wrongAcceptedHeldOut = 0;
};

struct PhotoFitCalibration {
  std::vector<PhotoFitCurve> curves;  // from every fit; empty when no |yaw| had enough
  std::vector<PhotoFitCalibrationRow> rows;
  int photos = 0;
  int judged = 0;  // fits the check judged (the others: no face, an error, no check)
  int noFace = 0;  // photos without a fit
};

// Fits every image (its truth in `truths`, one per image, any scheme readScoredTruth reads) with
// `model` stripped of any photo-fit curves, and learns them. InputError when the model has no
// check, when the lists differ in length, for a truth file that cannot be read, and when no |yaw|
// had enough right and wrong fits; Cancelled on `cancel`.
PhotoFitCalibration calibratePhotoFits(const ClmModel& model,
                                       const std::vector<std::filesystem::path>& images,
                                       const std::vector<std::filesystem::path>& truths,
                                       const PhotoFitCalibrationSettings& settings,
                                       const ProgressCallback& progress = {},
                                       const CancelToken* cancel = nullptr);

// The curves put into `model`'s check, and its provenance notes saying on how many photos of
// `source` (a folder or list) they were learnt.
void applyPhotoFitCalibration(ClmModel& model, const PhotoFitCalibration& calibration,
                              const std::filesystem::path& source);

// What `clm3d calibrate` and `clm3d train` print: per |yaw| of views the fits right and wrong and
// what the threshold of settings.fit does to them, by the check alone and, held out, by the
// curves; then the curves.
std::string formatPhotoFitCalibration(const PhotoFitCalibration& calibration,
                                      const PhotoFitCalibrationSettings& settings);

}  // namespace clm3d
