// The search options `clm3d fit` and `clm3d track` share (optimiser, scales, iterations, alpha
// masks, camera field of view, detector), declared once so both commands spell them the same.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "core/detect/face_detector.hpp"
#include "core/fit/fitter.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d::cli {

struct FitOptions {
  std::string optimiser = "fastncc";
  int scales = 0;
  int iterations = 4;
  bool noAlpha = false;
  double fovDeg = 40.0;
  std::string detector = "cascade";
  std::uint64_t seed = 1;
  int textureModes = 0;
  double shapePrior = OptimiserSettings{}.shapePrior;
  int rlmsRadius = OptimiserSettings{}.rlmsRadius;
  double rlmsSigma = OptimiserSettings{}.rlmsSigma;
  double rlmsRegularisation = OptimiserSettings{}.rlmsRegularisation;

  FitSettings settings() const;
  DetectorKind detectorKind() const;  // InputError for an unknown name
};

void addFitOptions(CLI::App& command, FitOptions& options);

// The start state of `--init FILE`: the model fitted to the file's points (.pts, .ljson, .csv;
// 68-point files converted). Problems are InputErrors that name the file.
FitState startFromPointsFile(const ClmModel& model, const Camera& camera,
                             const std::filesystem::path& path);

}  // namespace clm3d::cli
