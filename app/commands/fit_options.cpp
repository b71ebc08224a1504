#include "app/commands/fit_options.hpp"

#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"
#include "core/fit/optimiser.hpp"
#include "core/geometry/camera.hpp"
#include "core/track/batch_fit.hpp"

namespace clm3d::cli {

FitSettings FitOptions::settings() const {
  FitSettings result;
  result.optimiser = optimiser;
  result.scales = scales;
  result.maxIterations = iterations;
  result.alphaMask = !noAlpha;
  result.optimiserSettings.seed = seed;
  result.textureModes = textureModes;
  result.optimiserSettings.shapePrior = shapePrior;
  result.optimiserSettings.rlmsRadius = rlmsRadius;
  result.optimiserSettings.rlmsSigma = rlmsSigma;
  result.optimiserSettings.rlmsRegularisation = rlmsRegularisation;
  return result;
}

DetectorKind FitOptions::detectorKind() const {
  if (detector == "cascade") return DetectorKind::Cascade;
  if (detector == "dlib") return DetectorKind::DlibHog;
  throw InputError("unknown detector '" + detector + "' (valid: cascade, dlib)");
}

void addFitOptions(CLI::App& command, FitOptions& options) {
  options.fovDeg = kDefaultVerticalFovDeg;
  std::string names;
  for (const std::string& name : optimiserNames()) names += (names.empty() ? "" : ", ") + name;
  command.add_option("--optimiser", options.optimiser, "search optimiser: " + names)
      ->capture_default_str();
  command
      .add_option("--scales", options.scales, "pyramid scales searched (0 = all of the model's)")
      ->capture_default_str()
      ->check(CLI::Range(0, 8));
  command.add_option("--iterations", options.iterations, "iterations per scale")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  command.add_flag("--no-alpha", options.noAlpha, "do not mask patches with the alpha masks");
  command.add_option("--fov", options.fovDeg, "vertical field of view of the camera, degrees")
      ->capture_default_str()
      ->check(CLI::Range(5.0, 150.0));
  command
      .add_option("--detector", options.detector, "face detector: cascade (OpenCV) or dlib (HOG)")
      ->capture_default_str();
  command
      .add_option("--shape-prior", options.shapePrior,
                  "weight of the shape prior in gauss-newton and fastncc (0 = none)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e6));
  command
      .add_option("--texture-modes", options.textureModes,
                  "texture modes used to synthesise the templates (0 = all)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  command.add_option("--seed", options.seed, "random seed (condensation)")->capture_default_str();
  command
      .add_option("--rlms-radius", options.rlmsRadius,
                  "rlms: search window radius around each landmark (pixels of each scale)")
      ->capture_default_str()
      ->check(CLI::Range(1, 32));
  command
      .add_option("--rlms-sigma", options.rlmsSigma,
                  "rlms: standard deviation of the mean-shift kernel (pixels of each scale)")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 32.0));
  command
      .add_option("--rlms-regularisation", options.rlmsRegularisation,
                  "rlms: weight of the shape prior (squared pixels)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e6));
}

FitState startFromPointsFile(const ClmModel& model, const Camera& camera,
                             const std::filesystem::path& path) {
  return stateFromPointsFile(model, camera, path);
}

}  // namespace clm3d::cli
