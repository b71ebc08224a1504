// clm3d fit: finds the landmarks in one image (--image I --out F) or in many with the model loaded
// once (--images DIR|LIST --out-dir DIR: STEM.pts per image and summary.csv). Both go through
// core/track/batch_fit's ImageFitter: initialise from a face detector or from given points, run
// the CLM search, write the points. Ctrl-C stops a batch after the current image.
#include <atomic>
#include <csignal>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/fit_options.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "core/common/error.hpp"
#include "core/model/model_file.hpp"
#include "core/track/batch_fit.hpp"
#include "core/track/fit_overlay.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct FitArgs {
  fs::path model, image, init, out, overlay;
  fs::path images, outDir, initDir;
  bool quiet = false;
  bool keepRejected = false;
  double startOffset = 0.0;
  FitOptions fit;
};

ImageFitSettings imageFitSettings(const FitArgs& args) {
  ImageFitSettings settings = clm3d::imageFitSettings(args.fit.tracker, args.fit.fovDeg);
  settings.startOffset = args.startOffset;
  settings.startOffsetSeed = args.fit.seed();
  settings.keepRejected = args.keepRejected;
  return settings;
}

void runSingleFit(const FitArgs& args) {
  if (args.out.empty()) throw CLI::ValidationError("--out", "--image needs --out F.pts");
  const ClmModel model = loadModel(args.model);
  ImageFitter fitter(model, imageFitSettings(args));
  const ImageFitOutcome outcome = fitter.fitFile(args.image, args.init, args.out);
  if (outcome.status == ImageFitStatus::NoFace) {
    throw InputError(outcome.message + " (give the start points with --init)");
  }
  if (outcome.status != ImageFitStatus::Ok && outcome.status != ImageFitStatus::Rejected) {
    throw InputError(outcome.message);
  }
  const FitResult& fit = *outcome.fit;
  const bool rejected = outcome.status == ImageFitStatus::Rejected;
  // The overlay first: it shows where a rejected fit went.
  if (!args.overlay.empty()) {
    TrackStep step;
    step.fit = fit;
    step.row.success = !rejected;
    step.row.confidence = fit.confidence;
    cv::Mat drawn = fitter.lastImage().clone();
    drawFitOverlay(drawn, step, *fitter.lastFitter(), model.scheme());
    writeImage(args.overlay, drawn);
    std::cout << "overlay: " << args.overlay.string() << '\n';
  }
  if (rejected && !args.keepRejected) {
    throw InputError(outcome.message + "; no points written (--keep-rejected writes them)");
  }
  if (rejected) std::cerr << "warning: " << outcome.message << '\n';
  std::cout << std::fixed << std::setprecision(3) << (rejected ? "rejected " : "fitted ")
            << args.image.string() << " -> " << args.out.string() << ": confidence "
            << fit.confidence << ", view (pitch " << outcome.viewPitchDeg << ", yaw "
            << outcome.viewYawDeg << "), " << fit.iterations << " iterations"
            << (fit.converged ? "" : " (not converged)") << ", " << std::setprecision(2)
            << outcome.fitMilliseconds << " ms\n";
}

// Exit code 1 when any image had an error (after the whole batch and its summary), else 0.
void runBatchFit(const FitArgs& args) {
  if (args.outDir.empty()) throw CLI::ValidationError("--out-dir", "--images needs --out-dir DIR");
  BatchFitJob job;
  job.images = listImages(args.images);
  job.outDir = args.outDir;
  job.initDir = args.initDir;
  if (!job.initDir.empty() && !fs::is_directory(job.initDir)) {
    throwInputError(job.initDir, "no such folder (--init-dir)");
  }
  const ClmModel model = loadModel(args.model);
  InterruptScope interrupt;
  CliProgress progress(CliProgress::Style::Lines, args.quiet);
  const BatchFitSummary summary =
      fitImages(model, job, imageFitSettings(args), progress.callback(), &interrupt.token());
  interrupt.release();
  double fitSum = 0.0;
  for (const ImageFitOutcome& outcome : summary.outcomes) {
    if (outcome.status == ImageFitStatus::Ok) fitSum += outcome.fitMilliseconds;
    if (outcome.status == ImageFitStatus::Error) std::cerr << "error: " << outcome.message << '\n';
    if (outcome.status == ImageFitStatus::Rejected) {
      std::cerr << "rejected: " << outcome.message << '\n';
    }
  }
  std::cout << std::fixed << std::setprecision(1) << "fitted " << summary.ok << " of "
            << summary.outcomes.size() << " images (" << summary.rejected
            << " rejected by the point check" << (args.keepRejected ? ", points kept" : "") << ", "
            << summary.noFace << " without a face, " << summary.errors << " errors), mean fit "
            << (summary.ok > 0 ? fitSum / summary.ok : 0.0) << " ms -> " << args.outDir.string()
            << " (summary: " << summary.summaryCsv.string() << ")\n";
  if (summary.errors > 0) {
    throw InputError(std::to_string(summary.errors) + " of " +
                     std::to_string(summary.outcomes.size()) + " images could not be fitted (see " +
                     summary.summaryCsv.string() + ")");
  }
}

void runFit(const FitArgs& args) {
  if (args.image.empty() == args.images.empty()) {
    throw CLI::ValidationError("--image/--images",
                               "give either --image I --out F (one image) or --images DIR|LIST "
                               "--out-dir DIR (many)");
  }
  if (!args.image.empty()) {
    if (!args.outDir.empty() || !args.initDir.empty()) {
      throw CLI::ValidationError("--out-dir/--init-dir", "go with --images, not --image");
    }
    runSingleFit(args);
  } else {
    if (!args.out.empty() || !args.init.empty() || !args.overlay.empty()) {
      throw CLI::ValidationError("--out/--init/--overlay",
                                 "go with --image; a batch (--images) takes --out-dir and "
                                 "--init-dir");
    }
    runBatchFit(args);
  }
}

}  // namespace

void addFitCommand(CLI::App& root) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* command = root.add_subcommand(
      "fit", "find the landmarks in one image, or in many with the model loaded once");
  command->add_option("--model", args->model, "trained model (.clm3d)")->required();
  auto* image = command->add_option("--image", args->image, "image to search");
  auto* images = command->add_option(
      "--images", args->images,
      "images to search: a folder (every .jpg, .jpeg, .png, .ppm, .bmp, sorted) or a text file "
      "with one image path per line (relative to the file's folder; # comments)");
  image->excludes(images);
  command->add_option("--init", args->init,
                      "start from these points (.pts, .ljson, .csv; 68-point files are converted)");
  command->add_option("--out", args->out, "where to write the points (.pts, .ljson or .csv)");
  command->add_option("--overlay", args->overlay, "also write the image with the fit drawn on it");
  command->add_option("--out-dir", args->outDir,
                      "with --images: folder for STEM.pts per image and summary.csv");
  command->add_option("--init-dir", args->initDir,
                      "with --images: start each image from STEM.pts, .ljson or .csv in this "
                      "folder instead of the face detector");
  command->add_flag("--quiet", args->quiet, "with --images: no per-image progress on stderr");
  command->add_flag("--keep-rejected", args->keepRejected,
                    "write the points of a fit that the model's point check rejects (status "
                    "rejected; by default they are not written, as a tracker does not report such "
                    "a frame as tracked)");
  command
      ->add_option("--start-offset", args->startOffset,
                   "move every start by this share of its eye distance, in a direction drawn per "
                   "image from --seed (failure-detection experiments: wrong fits on purpose)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 5.0));
  addFitOptions(*command, args->fit, OptionCommand::Fit);
  command->callback([args] { runFit(*args); });
}

}  // namespace clm3d::cli
