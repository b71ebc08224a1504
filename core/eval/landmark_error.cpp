#include "core/eval/landmark_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/common/error.hpp"
#include "core/eval/statistics.hpp"

namespace clm3d {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

bool hasPoint(const Eigen::Matrix2Xd& points, int i) {
  return std::isfinite(points(0, i)) && std::isfinite(points(1, i));
}

// Error of one truth frame against its prediction row (nullptr when the prediction lacks it).
FrameError frameError(const TrackRow& truth, const TrackRow* prediction, const Scheme& scheme,
                      const EvalOptions& options) {
  const int n = static_cast<int>(truth.points.cols());
  FrameError result;
  result.frame = truth.frame;
  result.pointErrors.assign(static_cast<std::size_t>(n), kNan);
  result.error = kNan;
  const auto [first, second] = scheme.normalisationPair();
  if (hasPoint(truth.points, first) && hasPoint(truth.points, second)) {
    result.interOcular = (truth.points.col(first) - truth.points.col(second)).norm();
  }
  result.normalised = result.interOcular > 1e-9;
  result.predicted = prediction != nullptr;
  result.success = prediction != nullptr && prediction->success;
  if (!result.normalised || prediction == nullptr) return result;

  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < n; ++i) {
    if (!hasPoint(truth.points, i) || !hasPoint(prediction->points, i)) continue;
    const double e = (prediction->points.col(i) - truth.points.col(i)).norm() / result.interOcular;
    result.pointErrors[static_cast<std::size_t>(i)] = e;
    sum += e;
    ++count;
  }
  if (count > 0) result.error = sum / count;
  result.converged = result.success && count > 0 && result.error < options.threshold;
  return result;
}

// Jitter of every frame whose previous frame is in the truth too and succeeded in both, and the
// summary's jitter and lag (landmark_error.hpp). truth: rows in frame order, matching `frames`.
void measureMotion(const TrackTable& truth,
                   const std::unordered_map<int, const TrackRow*>& predictionOf,
                   std::vector<FrameError>& frames, ErrorSummary& summary) {
  const auto succeeded = [&](int frame) -> const TrackRow* {
    const auto it = predictionOf.find(frame);
    return it != predictionOf.end() && it->second->success ? it->second : nullptr;
  };
  double jitterSum = 0.0;
  double alongMotion = 0.0;  // sum of (p_t - g_t) . (g_t - g_t-1)
  double motionSquared = 0.0;
  for (std::size_t f = 1; f < frames.size(); ++f) {
    const TrackRow& now = truth.rows[f];
    const TrackRow& before = truth.rows[f - 1];
    FrameError& frame = frames[f];
    if (before.frame != now.frame - 1 || !frame.normalised) continue;
    const TrackRow* predicted = succeeded(now.frame);
    const TrackRow* previous = succeeded(before.frame);
    if (predicted == nullptr || previous == nullptr) continue;
    double sum = 0.0;
    int count = 0;
    for (int i = 0; i < static_cast<int>(now.points.cols()); ++i) {
      if (!hasPoint(now.points, i) || !hasPoint(before.points, i) ||
          !hasPoint(predicted->points, i) || !hasPoint(previous->points, i)) {
        continue;
      }
      const Eigen::Vector2d truthMotion = now.points.col(i) - before.points.col(i);
      const Eigen::Vector2d motion = predicted->points.col(i) - previous->points.col(i);
      sum += (motion - truthMotion).norm() / frame.interOcular;
      alongMotion += (predicted->points.col(i) - now.points.col(i)).dot(truthMotion);
      motionSquared += truthMotion.squaredNorm();
      ++count;
    }
    if (count == 0) continue;
    frame.jitter = sum / count;
    jitterSum += frame.jitter;
    ++summary.jitterFrames;
  }
  if (summary.jitterFrames > 0) summary.jitter = jitterSum / summary.jitterFrames;
  if (motionSquared > 1e-12) summary.lagFrames = -alongMotion / motionSquared;
}

ErrorSummary summarise(const std::vector<FrameError>& frames, const TrackTable& truth,
                       const Scheme& scheme, const EvalOptions& options) {
  ErrorSummary s;
  s.truthFrames = static_cast<int>(frames.size());
  std::vector<double> frameErrors;
  std::vector<double> allPointErrors;
  const auto& regions = scheme.regions();
  std::vector<std::vector<double>> regionErrors(regions.size());
  std::vector<int> regionTrue(regions.size(), 0);
  std::vector<int> regionFound(regions.size(), 0);

  for (std::size_t f = 0; f < frames.size(); ++f) {
    const auto& frame = frames[f];
    if (!frame.normalised) continue;
    ++s.normalisedFrames;
    s.predictedFrames += frame.predicted ? 1 : 0;
    s.succeededFrames += frame.success ? 1 : 0;
    s.convergedFrames += frame.converged ? 1 : 0;
    if (std::isfinite(frame.error)) {
      ++s.scoredFrames;
      frameErrors.push_back(frame.error);
    }
    const auto& truthPoints = truth.rows[f].points;
    for (int i = 0; i < static_cast<int>(frame.pointErrors.size()); ++i) {
      if (!hasPoint(truthPoints, i)) continue;
      const int region = scheme.regionOf(i);
      ++s.truePoints;
      if (region >= 0) ++regionTrue[static_cast<std::size_t>(region)];
      const double e = frame.pointErrors[static_cast<std::size_t>(i)];
      if (std::isnan(e)) continue;
      allPointErrors.push_back(e);
      if (region >= 0) regionErrors[static_cast<std::size_t>(region)].push_back(e);
      if (e <= options.threshold) {
        ++s.foundPoints;
        if (region >= 0) ++regionFound[static_cast<std::size_t>(region)];
      }
    }
  }

  const auto stats = describe(frameErrors);
  s.mean = stats.mean;
  s.median = stats.median;
  s.sd = stats.sd;
  s.min = stats.min;
  s.max = stats.max;
  const auto share = [](int part, int whole) {
    return whole > 0 ? static_cast<double>(part) / whole : kNan;
  };
  s.convergenceRate = share(s.convergedFrames, s.normalisedFrames);
  s.withinThreshold = share(s.foundPoints, s.truePoints);
  s.meanPointError = describe(allPointErrors).mean;

  for (std::size_t r = 0; r < regions.size(); ++r) {
    const auto regionStats = describe(regionErrors[r]);
    RegionError region;
    region.name = regions[r].name;
    region.colour = regions[r].colour;
    region.points = regionStats.count;
    region.mean = regionStats.mean;
    region.sd = regionStats.sd;
    region.withinThreshold = share(regionFound[r], regionTrue[r]);
    s.regions.push_back(region);
  }

  // Shares against every normalised frame and every true point, so that missing predictions
  // count as above every threshold: a tracker that drops frames does not look better for it.
  std::sort(frameErrors.begin(), frameErrors.end());
  std::sort(allPointErrors.begin(), allPointErrors.end());
  const int steps = options.cdfStep > 0.0
                        ? static_cast<int>(std::floor(options.cdfMax / options.cdfStep + 1e-9))
                        : 0;
  for (int k = 0; k <= steps; ++k) {
    CdfSample sample;
    sample.threshold = k * options.cdfStep;
    const auto below = [&](const std::vector<double>& sorted) {
      return static_cast<int>(std::upper_bound(sorted.begin(), sorted.end(), sample.threshold) -
                              sorted.begin());
    };
    sample.frames = share(below(frameErrors), s.normalisedFrames);
    sample.points = share(below(allPointErrors), s.truePoints);
    s.cdf.push_back(sample);
  }
  return s;
}

}  // namespace

SequenceEvaluation evaluateSequence(const TrackTable& truth, const TrackTable& prediction,
                                    const Scheme& scheme, const EvalOptions& options,
                                    const std::string& truthName,
                                    const std::string& predictionName) {
  if (truth.landmarkCount != scheme.size()) {
    throwInputError(truthName, "has " + std::to_string(truth.landmarkCount) +
                                   " landmarks (x_1..x_" + std::to_string(truth.landmarkCount) +
                                   ") but scheme " + scheme.name() + " has " +
                                   std::to_string(scheme.size()));
  }
  if (prediction.landmarkCount != truth.landmarkCount) {
    throwInputError(predictionName, "has " + std::to_string(prediction.landmarkCount) +
                                        " landmarks but the ground truth " + truthName + " has " +
                                        std::to_string(truth.landmarkCount));
  }
  if (!(options.threshold > 0.0)) throw InputError("evaluation threshold must be positive");
  if (truth.rows.empty()) throwInputError(truthName, "has no frames");

  std::unordered_map<int, const TrackRow*> predictionOf;
  for (const auto& row : prediction.rows) predictionOf.emplace(row.frame, &row);

  // Truth rows in frame order (tables are normally written in order; this makes sure).
  TrackTable sortedTruth = truth;
  std::stable_sort(sortedTruth.rows.begin(), sortedTruth.rows.end(),
                   [](const TrackRow& a, const TrackRow& b) { return a.frame < b.frame; });

  SequenceEvaluation result;
  result.label = predictionName;
  result.source = predictionName;
  int matched = 0;
  for (const auto& row : sortedTruth.rows) {
    const auto it = predictionOf.find(row.frame);
    const TrackRow* predicted = it == predictionOf.end() ? nullptr : it->second;
    matched += predicted != nullptr ? 1 : 0;
    result.frames.push_back(frameError(row, predicted, scheme, options));
  }
  result.summary = summarise(result.frames, sortedTruth, scheme, options);
  measureMotion(sortedTruth, predictionOf, result.frames, result.summary);
  result.summary.extraPredictionRows = static_cast<int>(prediction.rows.size()) - matched;
  if (result.summary.normalisedFrames == 0) {
    const auto [first, second] = scheme.normalisationPair();
    throwInputError(truthName, "no frame has both normalisation points " + scheme.id(first) + " (" +
                                   std::to_string(first + 1) + ") and " + scheme.id(second) + " (" +
                                   std::to_string(second + 1) +
                                   ") apart, so no error can be normalised");
  }
  return result;
}

std::vector<double> scoredFrameErrors(const SequenceEvaluation& evaluation) {
  std::vector<double> errors;
  for (const auto& frame : evaluation.frames) {
    if (frame.normalised && std::isfinite(frame.error)) errors.push_back(frame.error);
  }
  return errors;
}

}  // namespace clm3d
