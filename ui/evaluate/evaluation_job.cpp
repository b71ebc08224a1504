#include "ui/evaluate/evaluation_job.hpp"

#include <map>

#include "core/common/error.hpp"
#include "core/track/track_table.hpp"

namespace clm3d::ui {

std::vector<std::string> predictionLabels(const std::vector<std::filesystem::path>& predictions) {
  std::map<std::string, int> uses;
  for (const auto& path : predictions) ++uses[path.stem().string()];
  std::vector<std::string> labels;
  for (const auto& path : predictions) {
    const auto stem = path.stem().string();
    const auto parent = path.parent_path().filename().string();
    labels.push_back(uses[stem] > 1 && !parent.empty() ? parent + "/" + stem : stem);
  }
  return labels;
}

const Scheme& schemeForLandmarkCount(int landmarkCount, const std::filesystem::path& truthFile) {
  for (const Scheme* scheme : {&Scheme::thesis25(), &Scheme::ibug68()}) {
    if (scheme->size() == landmarkCount) return *scheme;
  }
  throwInputError(truthFile, "has " + std::to_string(landmarkCount) +
                                 " landmarks; the studio evaluates thesis25 (25) and ibug68 (68) "
                                 "(clm3d eval --scheme FILE.json evaluates others)");
}

EvaluationReport runEvaluation(const EvaluationRequest& request, const ProgressCallback& progress,
                               const CancelToken& cancel) {
  if (progress) progress(0.0, "reading the ground truth");
  const int landmarks = readTrackTable(request.truth).landmarkCount;
  cancel.throwIfCancelled();
  const Scheme& scheme = schemeForLandmarkCount(landmarks, request.truth);
  EvalOptions options;
  options.threshold = request.threshold;
  if (progress) progress(0.2, "evaluating");
  auto report = evaluateTrackFiles(request.truth, request.predictions,
                                   predictionLabels(request.predictions), scheme, options);
  cancel.throwIfCancelled();
  if (progress) progress(1.0, "done");
  return report;
}

}  // namespace clm3d::ui
