#include "core/eval/calibrate_request.hpp"

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
      integerOption<R>(commandOption("image-min-fits",
                                     "a view's |yaw| with at least this many fits also reads the "
                                     "image at the fit's points (the image term); 0: the check's "
                                     "log-odds alone",
                                     0, 1000000),
                       [](R& r) -> int& { return r.settings.imageMinFits; }),
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
  applyPhotoFitCalibration(model, calibration, request.images);
  saveModel(model, request.out);

  std::ostringstream out;
  out << "calibrated the check of " << request.model.string() << " on ";
  out << formatPhotoFitCalibration(calibration, request.settings);
  out << "calibrated model: " << request.out.string() << "\n";
  return out.str();
}

}  // namespace clm3d
