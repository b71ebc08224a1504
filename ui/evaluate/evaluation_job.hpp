// What the evaluate page asks core to compute, and the call that computes it on the worker
// thread: the same evaluateTrackFiles as `clm3d eval`, with the scheme chosen from the ground
// truth's landmark count and legend names made unique, so the page and the CLI agree.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/eval/eval_report.hpp"

namespace clm3d::ui {

struct EvaluationRequest {
  std::filesystem::path truth;
  std::vector<std::filesystem::path> predictions;
  double threshold = 0.18;
};

// The file names without extension, with the parent folder prepended where two are alike.
std::vector<std::string> predictionLabels(const std::vector<std::filesystem::path>& predictions);

// Built-in scheme with this many landmarks (thesis25, ibug68); InputError naming truthFile
// otherwise.
const Scheme& schemeForLandmarkCount(int landmarkCount, const std::filesystem::path& truthFile);

// Reads the files and evaluates (InputError naming the file at fault); Cancelled if cancel was
// triggered meanwhile.
EvaluationReport runEvaluation(const EvaluationRequest& request, const ProgressCallback& progress,
                               const CancelToken& cancel);

}  // namespace clm3d::ui
