// What `clm3d eval-points` is asked for, described once as an option table (the CLI builds the
// command's options from it), and its run: point files of one image against a mark-up
// (core/eval/point_set_error), or folders of them paired by file stem with per-|yaw|-band tables
// and the confidence ROC (core/eval/point_folder_error, confidence_roc). Options that do not go
// together are UsageErrors naming them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/command_report.hpp"
#include "core/common/option_table.hpp"
#include "core/track/face_search_settings.hpp"

namespace clm3d {

struct EvalPointsRequest {
  std::filesystem::path truth;
  std::vector<std::filesystem::path> predictions;
  std::filesystem::path truthDir;
  std::vector<std::filesystem::path> predictionDirs;
  std::vector<std::string> labels;
  std::filesystem::path csv;
  std::string points;
  std::string scheme = "thesis25";
  double threshold = 0.18;
  bool json = false;
  bool roc = false;
  bool sameFaces = false;
  double wrongAbove = 0.15;
  // For --roc: the threshold whose counts are printed (the default --min-probability).
  double acceptAt = FaceSearchSettings{}.minProbability;
  double offFaceAbove = 0.08;
  std::filesystem::path poses, model;
  std::string yawBands = "0,30,60,90";
  std::filesystem::path bandTable, out;
};

// Every option of `clm3d eval-points`, in its help's order.
const std::vector<Option<EvalPointsRequest>>& evalPointsOptions();

// The report as text (or JSON with --json, the notes of written files then on stderr).
CommandReport runEvalPoints(const EvalPointsRequest& request);

}  // namespace clm3d
