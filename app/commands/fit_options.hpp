// The search and tracker options of `clm3d fit`, `clm3d track` and `clm3d batch`, built from
// core's one description of them (core/track/tracker_options.hpp: name, kind, range, default,
// help, the commands that take it), so the commands and the studio's Track page spell, limit and
// explain them the same way and each command takes only the options its code reads.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>

#include "core/detect/face_detector.hpp"
#include "core/fit/fitter.hpp"
#include "core/model/clm_model.hpp"
#include "core/track/tracker_options.hpp"

namespace clm3d::cli {

struct FitOptions {
  // Filled by the table's options that the command takes (addFitOptions).
  TrackerSettings tracker;  // --fov sets tracker.verticalFovDeg

  FitSettings settings() const { return tracker.fit; }
  DetectorKind detectorKind() const { return tracker.detector; }
  std::uint64_t seed() const { return tracker.fit.optimiserSettings.seed; }
};

// The tracker table's options that `which` takes (Fit, Track or Batch: TrackerOption::commands)
// and --fov. `options` must outlive the command's parsing.
void addFitOptions(CLI::App& command, FitOptions& options, OptionCommand which);

}  // namespace clm3d::cli
