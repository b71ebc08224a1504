#include "core/eval/calibrate_request.hpp"

#include <iomanip>
#include <sstream>

#include "core/common/error.hpp"
#include "core/common/image_list.hpp"
#include "core/detect/detector_evaluation.hpp"
#include "core/model/model_file.hpp"

namespace clm3d {
namespace calibrate_request_detail {

using R = CalibrateRequest;

std::vector<Option<R>> makeOptions() {
  return {
      textOption<R>(requiredOption("model", "model to calibrate (.clm3d, trained with photos)"),
                    &R::model),
      textOption<R>(requiredOption("images",
                                   "annotated photos the model did not learn from: a folder, or "
                                   "a list file with one image path per line"),
                    &R::images),
      textOption<R>(commandOption("truth-dir",
                                  "folder of the truth STEM.pts (68 iBUG, 21 AFLW or the model's "
                                  "scheme); default: beside each image"),
                    &R::truthDir),
      textOption<R>(requiredOption("out", "calibrated model to write (.clm3d)"), &R::out),
      realOption<R>(commandOption("right-below",
                                  "a fit is right when its mean error is at most this share of "
                                  "the truth's face box",
                                  0.01, 1.0),
                    [](R& r) -> double& { return r.settings.rightBelow; }),
      integerOption<R>(commandOption("min-each",
                                     "a view's |yaw| gets its own curve from at least this many "
                                     "right and this many wrong fits (the others take the "
                                     "nearest |yaw|'s)",
                                     1, 100000),
                       [](R& r) -> int& { return r.settings.minEach; }),
      integerOption<R>(commandOption("threads", "worker threads (0: one per core)", 0, 256),
                       [](R& r) -> int& { return r.settings.threads; }),
      flagOption<R>(commandOption("quiet", "no progress on stderr"), &R::quiet),
  };
}

}  // namespace calibrate_request_detail

const std::vector<Option<CalibrateRequest>>& calibrateOptions() {
  static const std::vector<Option<CalibrateRequest>> table =
      calibrate_request_detail::makeOptions();
  return table;
}

std::string runCalibrate(const CalibrateRequest& request, const ProgressCallback& progress,
                         const CancelToken* cancel) {
  ClmModel model = loadModel(request.model);
  if (model.refiner.check.empty()) {
    throw InputError(fileMessage(request.model,
                                 "the model has no point check to calibrate (a "
                                 "model trained with 20 or more photos has one)"));
  }
  const std::vector<std::filesystem::path> images = listImages(request.images);
  const std::vector<std::filesystem::path> truths = findTruthFiles(images, request.truthDir);
  const PhotoFitCalibration calibration =
      calibratePhotoFits(model, images, truths, request.settings, progress, cancel);
  model.refiner.check.photoFitCurves = calibration.curves;
  saveModel(model, request.out);

  std::ostringstream out;
  out << "calibrated the check of " << request.model.string() << " on " << calibration.photos
      << " photos (" << calibration.judged << " fits judged by the check, " << calibration.noFace
      << " without a fit); a fit is right within " << request.settings.rightBelow
      << " of the face box\n";
  const double threshold = request.settings.fit.minProbability;
  out << "at probability >= " << threshold
      << ": right fits kept and wrong ones accepted, by the check alone -> by the curves learnt "
         "from the other half of the photos\n";
  out << "| view |yaw| | fits | right | wrong | curve | right kept | wrong accepted |\n"
      << "|---|---|---|---|---|---|---|\n";
  for (const PhotoFitCalibrationRow& row : calibration.rows) {
    out << "| " << row.viewYawDeg << " | " << row.right + row.wrong << " | " << row.right << " | "
        << row.wrong << " | " << (row.curve ? "own" : "nearest") << " | " << row.rightKeptBefore
        << " -> " << row.rightKeptHeldOut << " | " << row.wrongAcceptedBefore << " -> "
        << row.wrongAcceptedHeldOut << " |\n";
  }
  out << std::setprecision(4);
  for (const PhotoFitCurve& curve : calibration.curves) {
    out << "curve |yaw| " << curve.viewYawDeg << ": p = 1 / (1 + exp(-(" << curve.slope
        << " * log-odds of the check + " << curve.offset << ")))\n";
  }
  out << "calibrated model: " << request.out.string() << "\n";
  return out.str();
}

}  // namespace clm3d
