// The search and tracker options of `clm3d fit` and `clm3d track`, built from core's one
// description of them (core/track/tracker_options.hpp: name, kind, range, default, help), so both
// commands and the studio's Track page spell, limit and explain them the same way.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>

#include "core/detect/face_detector.hpp"
#include "core/fit/fitter.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/clm_model.hpp"
#include "core/track/tracker_options.hpp"

namespace clm3d::cli {

struct FitOptions {
  // Filled by the table's options: the Search ones (addFitOptions), and for `clm3d track` the
  // Track ones too (addTrackerOptions).
  TrackerSettings tracker;
  double fovDeg = kDefaultVerticalFovDeg;

  FitSettings settings() const { return tracker.fit; }
  DetectorKind detectorKind() const { return tracker.detector; }
  std::uint64_t seed() const { return tracker.fit.optimiserSettings.seed; }
};

// The table's Search options and --fov. `options` must outlive the command's parsing.
void addFitOptions(CLI::App& command, FitOptions& options);
// The table's options of `scope` (e.g. Track for `clm3d track`), writing into `settings`, which
// must outlive the command's parsing.
void addTrackerOptions(CLI::App& command, TrackerSettings& settings, OptionScope scope);

// The start state of `--init FILE`: the model fitted to the file's points (.pts, .ljson, .csv;
// 68-point files converted). Problems are InputErrors that name the file.
FitState startFromPointsFile(const ClmModel& model, const Camera& camera,
                             const std::filesystem::path& path);

}  // namespace clm3d::cli
