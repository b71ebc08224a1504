#include "app/commands/fit_options.hpp"

#include "app/commands/option_cli.hpp"
#include "core/detect/initialisation.hpp"
#include "core/geometry/camera.hpp"
#include "core/track/batch_fit.hpp"

namespace clm3d::cli {

void addFitOptions(CLI::App& command, FitOptions& options, OptionCommand which) {
  addTableOptions(command, trackerOptions(), which, options.tracker);
  command.add_option("--fov", options.fovDeg, "vertical field of view of the camera, degrees")
      ->capture_default_str()
      ->check(CLI::Range(5.0, 150.0));
}

FitState startFromPointsFile(const ClmModel& model, const Camera& camera,
                             const std::filesystem::path& path) {
  return stateFromPointsFile(model, camera, path);
}

}  // namespace clm3d::cli
