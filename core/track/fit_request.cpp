#include "core/track/fit_request.hpp"

#include <iomanip>
#include <numeric>
#include <sstream>

#include "core/common/error.hpp"
#include "core/common/image_list.hpp"
#include "core/common/median.hpp"
#include "core/model/model_file.hpp"
#include "core/track/batch_fit.hpp"
#include "core/track/fit_overlay.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {
namespace fit_request_detail {

namespace fs = std::filesystem;
using R = FitRequest;

std::vector<Option<R>> makeOptions() {
  const auto path = [](const char* name, const char* help, fs::path R::*field) {
    return textOption<R>(commandOption(name, help), field);
  };
  return {
      textOption<R>(requiredOption("model", "trained model (.clm3d)"), &R::model),
      path("image", "image to search", &R::image),
      path("images",
           "images to search: a folder (every .jpg, .jpeg, .png, .ppm, .bmp, sorted) or a text "
           "file with one image path per line (relative to the file's folder; # comments)",
           &R::images),
      path("init", "start from these points (.pts, .ljson, .csv; 68-point files are converted)",
           &R::init),
      path("out", "where to write the points (.pts, .ljson or .csv)", &R::out),
      path("overlay", "also write the image with the fit drawn on it", &R::overlay),
      path("out-dir", "with --images: folder for STEM.pts per image and summary.csv", &R::outDir),
      path("init-dir",
           "with --images: start each image from STEM.pts, .ljson or .csv in this folder instead "
           "of the face detector",
           &R::initDir),
      flagOption<R>(commandOption("quiet", "with --images: no per-image progress on stderr"),
                    &R::quiet),
      flagOption<R>(commandOption("keep-rejected",
                                  "write the points of a fit that the model's point check rejects "
                                  "(status rejected; by default they are not written, as a "
                                  "tracker does not report such a frame as tracked)"),
                    &R::keepRejected),
      realOption<R>(commandOption("start-offset",
                                  "move every start by this share of its eye distance, in a "
                                  "direction drawn per image from --seed (failure-detection "
                                  "experiments: wrong fits on purpose)",
                                  0.0, 5.0),
                    &R::startOffset),
  };
}

ImageFitSettings settingsOf(const R& args) {
  ImageFitSettings settings = imageFitSettings(args.tracker);
  settings.startOffset = args.startOffset;
  settings.startOffsetSeed = args.tracker.fit.optimiserSettings.seed;
  settings.keepRejected = args.keepRejected;
  return settings;
}

CommandReport fitOne(const R& args) {
  if (args.out.empty()) throw UsageError("--out", "--image needs --out F.pts");
  const ClmModel model = loadModel(args.model);
  ImageFitter fitter(model, settingsOf(args));
  const ImageFitOutcome outcome = fitter.fitFile(args.image, args.init, args.out);
  if (outcome.status == ImageFitStatus::NoFace) {
    throw InputError(outcome.message + " (give the start points with --init)");
  }
  if (outcome.status != ImageFitStatus::Ok && outcome.status != ImageFitStatus::Rejected) {
    throw InputError(outcome.message);
  }
  const FitResult& fit = *outcome.fit;
  const bool rejected = outcome.status == ImageFitStatus::Rejected;
  CommandReport output;
  std::ostringstream text;
  // The overlay first: it shows where a rejected fit went.
  if (!args.overlay.empty()) {
    cv::Mat drawn = fitter.lastImage().clone();
    drawPhotoOverlay(drawn, fitter.lastImage(), fit, !rejected, args.image.filename().string(),
                     *fitter.lastFitter(), model.scheme());
    writeImage(args.overlay, drawn);
    text << "overlay: " << args.overlay.string() << '\n';
  }
  if (rejected && !args.keepRejected) {
    output.text = text.str();
    output.failure = outcome.message + "; no points written (--keep-rejected writes them)";
    return output;
  }
  if (rejected) output.warnings = "warning: " + outcome.message + '\n';
  text << std::fixed << std::setprecision(3) << (rejected ? "rejected " : "fitted ")
       << args.image.string() << " -> " << args.out.string() << ": probability " << fit.probability
       << " (" << toString(fit.probabilitySource) << "; search score " << fit.searchScore
       << "), view (pitch " << outcome.viewPitchDeg << ", yaw " << outcome.viewYawDeg << "), "
       << fit.iterations << " iterations" << (fit.converged ? "" : " (not converged)") << ", "
       << std::setprecision(2) << outcome.fitMilliseconds << " ms\n";
  output.text = text.str();
  return output;
}

// Fails (exit 1) when any image had an error, after the whole batch and its summary.
CommandReport fitMany(const R& args, const ProgressCallback& progress, const CancelToken* cancel) {
  if (args.outDir.empty()) throw UsageError("--out-dir", "--images needs --out-dir DIR");
  BatchFitJob job;
  job.images = listImages(args.images);
  job.outDir = args.outDir;
  job.initDir = args.initDir;
  if (!job.initDir.empty() && !fs::is_directory(job.initDir)) {
    throwInputError(job.initDir, "no such folder (--init-dir)");
  }
  const ClmModel model = loadModel(args.model);
  const BatchFitSummary summary = fitImages(model, job, settingsOf(args), progress, cancel);
  CommandReport output;
  std::vector<double> fitTimes;
  for (const ImageFitOutcome& outcome : summary.outcomes) {
    if (outcome.status == ImageFitStatus::Ok) fitTimes.push_back(outcome.fitMilliseconds);
    if (outcome.status == ImageFitStatus::Error)
      output.warnings += "error: " + outcome.message + '\n';
    if (outcome.status == ImageFitStatus::Rejected) {
      output.warnings += "rejected: " + outcome.message + '\n';
    }
  }
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << "fitted " << summary.ok << " of "
       << summary.outcomes.size() << " images (" << summary.rejected
       << " rejected by the point check" << (args.keepRejected ? ", points kept" : "") << ", "
       << summary.noFace << " without a face, " << summary.errors << " errors)";
  if (!fitTimes.empty()) {
    // Landmarking alone, as the summary's fit_ms: detection apart.
    const double mean = std::accumulate(fitTimes.begin(), fitTimes.end(), 0.0) /
                        static_cast<double>(fitTimes.size());
    text << ", fit median " << medianOf(fitTimes) << " ms (mean " << mean << ")";
  }
  text << " -> " << args.outDir.string() << " (summary: " << summary.summaryCsv.string() << ")\n";
  output.text = text.str();
  if (summary.errors > 0) {
    output.failure = std::to_string(summary.errors) + " of " +
                     std::to_string(summary.outcomes.size()) + " images could not be fitted (see " +
                     summary.summaryCsv.string() + ")";
  }
  return output;
}

}  // namespace fit_request_detail

const std::vector<Option<FitRequest>>& fitRequestOptions() {
  static const std::vector<Option<FitRequest>> table = fit_request_detail::makeOptions();
  return table;
}

CommandReport runFit(const FitRequest& args, const ProgressCallback& progress,
                     const CancelToken* cancel) {
  if (args.image.empty() == args.images.empty()) {
    throw UsageError("--image/--images",
                     "give either --image I --out F (one image) or --images DIR|LIST --out-dir DIR "
                     "(many)");
  }
  if (!args.image.empty()) {
    if (!args.outDir.empty() || !args.initDir.empty()) {
      throw UsageError("--out-dir/--init-dir", "go with --images, not --image");
    }
    return fit_request_detail::fitOne(args);
  }
  if (!args.out.empty() || !args.init.empty() || !args.overlay.empty()) {
    throw UsageError("--out/--init/--overlay",
                     "go with --image; a batch (--images) takes --out-dir and --init-dir");
  }
  return fit_request_detail::fitMany(args, progress, cancel);
}

}  // namespace clm3d
