// What `clm3d detect` is asked for, described once as an option table over the detector
// evaluation's settings (core/detect/detector_evaluation: the detector's options, the box
// calibration, the start error), and its run: the detectors measured on annotated photos, per
// |yaw| band with --poses (core/eval/yaw_bands), as text or JSON, the report written on demand.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/command_report.hpp"
#include "core/common/option_table.hpp"
#include "core/common/progress.hpp"
#include "core/detect/detector_evaluation.hpp"

namespace clm3d {

struct DetectRequest {
  std::filesystem::path images, truthDir, poses;
  std::string yawBands = "0,30,60,90";
  std::vector<std::string> detectors{"all"};
  DetectorEvaluationSettings settings;
  bool calibrate = false;
  std::string calibrateTo = "eyes";
  std::filesystem::path model;
  bool startError = false;
  std::vector<std::filesystem::path> calibrations;
  std::filesystem::path out;
  bool json = false;
  bool quiet = false;
};

// Every option of `clm3d detect`, in its help's order.
const std::vector<Option<DetectRequest>>& detectOptions();

// The report (text, or JSON with --json, the note of the written report then on stderr);
// `progress` hears each image.
CommandReport runDetect(const DetectRequest& request, const ProgressCallback& progress);

}  // namespace clm3d
