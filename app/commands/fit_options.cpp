#include "app/commands/fit_options.hpp"

#include <string>

#include "core/detect/initialisation.hpp"
#include "core/geometry/camera.hpp"
#include "core/track/batch_fit.hpp"

namespace clm3d::cli {

void addTrackerOptions(CLI::App& command, TrackerSettings& settings, OptionScope scope) {
  for (const TrackerOption& option : trackerOptions()) {
    if (option.scope != scope) continue;
    const std::string flag = "--" + option.name;
    if (option.kind == OptionKind::Flag) {
      command.add_flag_function(
          flag,
          [&settings, &option](std::int64_t count) {
            option.set(settings, count > 0 ? "true" : "false");
          },
          option.help);
      continue;
    }
    // Ranges are checked by CLI11 (bad usage, exit 2, the range in the help); the setter parses
    // and checks choices (InputError listing the valid ones, exit 1).
    CLI::Option* added = command.add_option_function<std::string>(
        flag, [&settings, &option](const std::string& text) { option.set(settings, text); },
        option.help);
    added->default_str(option.defaultText());
    if (option.kind == OptionKind::Integer) {
      added->type_name("INT")->check(CLI::Range(static_cast<std::int64_t>(option.minimum),
                                                static_cast<std::int64_t>(option.maximum)));
    } else if (option.kind == OptionKind::Real) {
      added->type_name("FLOAT")->check(CLI::Range(option.minimum, option.maximum));
    } else {
      added->type_name("NAME");
    }
  }
}

void addFitOptions(CLI::App& command, FitOptions& options) {
  addTrackerOptions(command, options.tracker, OptionScope::Search);
  command.add_option("--fov", options.fovDeg, "vertical field of view of the camera, degrees")
      ->capture_default_str()
      ->check(CLI::Range(5.0, 150.0));
}

FitState startFromPointsFile(const ClmModel& model, const Camera& camera,
                             const std::filesystem::path& path) {
  return stateFromPointsFile(model, camera, path);
}

}  // namespace clm3d::cli
