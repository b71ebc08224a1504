// What `clm3d calibrate` is asked for, described once as an option table, and its run: a model's
// point check calibrated on photo fits (core/eval/photo_fit_calibration), written as a new model.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/option_table.hpp"
#include "core/common/progress.hpp"
#include "core/eval/photo_fit_calibration.hpp"

namespace clm3d {

struct CalibrateRequest {
  std::filesystem::path model, images, truthDir, out;
  PhotoFitCalibrationSettings settings;
  bool quiet = false;
};

// Every option of `clm3d calibrate`, in its help's order.
const std::vector<Option<CalibrateRequest>>& calibrateOptions();

// Loads the model, fits and calibrates, writes the calibrated model (atomically); returns what the
// command prints: per |yaw| of views the fits right and wrong, and the right kept and wrong
// accepted at --min-probability before and, held out, after.
std::string runCalibrate(const CalibrateRequest& request, const ProgressCallback& progress,
                         const CancelToken* cancel);

}  // namespace clm3d
