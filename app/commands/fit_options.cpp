#include "app/commands/fit_options.hpp"

#include "app/commands/option_cli.hpp"

namespace clm3d::cli {

void addFitOptions(CLI::App& command, FitOptions& options, OptionCommand which) {
  addTableOptions(command, trackerOptions(), which, options.tracker);
  command
      .add_option("--fov", options.tracker.verticalFovDeg,
                  "vertical field of view of the camera, degrees (default: " +
                      std::to_string(static_cast<int>(kStillImageVerticalFovDeg)) +
                      " for still images, " +
                      std::to_string(static_cast<int>(kDefaultVerticalFovDeg)) + " for video)")
      ->check(CLI::Range(5.0, 150.0));
}

}  // namespace clm3d::cli
