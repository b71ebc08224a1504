// clm3d fit: finds the landmarks in one image: initialise from a face detector or from given
// points, run the CLM search, write the points (.pts, .ljson or .csv) and optionally an overlay.
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "app/commands/commands.hpp"
#include "app/commands/fit_options.hpp"
#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"
#include "core/model/model_file.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/fit_overlay.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct FitArgs {
  fs::path model, image, init, out, overlay;
  FitOptions fit;
};

void runFit(const FitArgs& args) {
  const ClmModel model = loadModel(args.model);
  const Scheme scheme = model.scheme();
  const cv::Mat image = readImage(args.image);
  const Camera camera = Camera::fromVerticalFov(image.cols, image.rows, args.fit.fovDeg);
  FitState start;
  if (!args.init.empty()) {
    start = startFromPointsFile(model, camera, args.init);
  } else {
    FaceDetector detector(args.fit.detectorKind());
    try {
      start = initialiseFromImage(model, camera, image, detector);
    } catch (const NoFaceFound&) {
      throw InputError(
          fileMessage(args.image, "no face found (give the start points with --init)"));
    }
  }
  Fitter fitter(model, camera, args.fit.settings());
  const auto begin = std::chrono::steady_clock::now();
  TrackStep step;
  step.fit = fitter.fit(image, start);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
  const FitResult& fit = *step.fit;

  LandmarkSet points(scheme.size(), 2);
  for (int i = 0; i < scheme.size(); ++i) points.set(i, Eigen::Vector2d(fit.points.col(i)));
  writeLandmarks(args.out, points, scheme);
  const ViewModel& view = model.views[static_cast<std::size_t>(fit.view)];
  std::cout << std::fixed << std::setprecision(3) << "fitted " << args.image.string() << " -> "
            << args.out.string() << ": confidence " << fit.confidence << ", view (pitch "
            << view.pitchDeg << ", yaw " << view.yawDeg << "), " << fit.iterations << " iterations"
            << (fit.converged ? "" : " (not converged)") << ", " << std::setprecision(2) << ms
            << " ms\n";
  if (!args.overlay.empty()) {
    step.row.success = true;
    step.row.confidence = fit.confidence;
    cv::Mat drawn = image.clone();
    drawFitOverlay(drawn, step, fitter, scheme);
    writeImage(args.overlay, drawn);
    std::cout << "overlay: " << args.overlay.string() << '\n';
  }
}

}  // namespace

void addFitCommand(CLI::App& root) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* command = root.add_subcommand("fit", "find the landmarks in one image");
  command->add_option("--model", args->model, "trained model (.clm3d)")->required();
  command->add_option("--image", args->image, "image to search")->required();
  command->add_option("--init", args->init,
                      "start from these points (.pts, .ljson, .csv; 68-point files are converted)");
  command->add_option("--out", args->out, "where to write the points (.pts, .ljson or .csv)")
      ->required();
  command->add_option("--overlay", args->overlay, "also write the image with the fit drawn on it");
  addFitOptions(*command, args->fit);
  command->callback([args] { runFit(*args); });
}

}  // namespace clm3d::cli
