#include "core/eval/landmark_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/common/error.hpp"
#include "core/common/number_text.hpp"
#include "core/eval/statistics.hpp"
#include "core/geometry/face_box.hpp"

namespace clm3d {
namespace {

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
  result.truePoints.assign(static_cast<std::size_t>(n), false);
  for (int i = 0; i < n; ++i)
    result.truePoints[static_cast<std::size_t>(i)] = hasPoint(truth.points, i);
  result.error = kNan;
  const auto [first, second] = scheme.normalisationPair();
  if (hasPoint(truth.points, first) && hasPoint(truth.points, second)) {
    result.interOcular = (truth.points.col(first) - truth.points.col(second)).norm();
  }
  result.faceSize = faceBoxSize(truth.points);
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
  if (count > 0 && result.faceSize > 1e-9) {
    result.boxError = result.error * result.interOcular / result.faceSize;
  }
  result.converged = result.success && count > 0 && result.error < options.threshold;
  return result;
}

// What the jitter and lag of a summary are made of, summed so that sequences pool.
struct MotionSums {
  double jitterSum = 0.0;
  int jitterFrames = 0;
  double nmjSum = 0.0;  // over the frames with a jitter and a face box
  int nmjFrames = 0;
  double alongMotion = 0.0;  // sum of (p_t - g_t) . (g_t - g_t-1)
  double motionSquared = 0.0;
};

// Jitter of every frame whose previous frame is in the truth too and succeeded in both, and the
// sums behind the summary's jitter and lag (landmark_error.hpp). truth: rows in frame order,
// matching `frames`.
void measureMotion(const TrackTable& truth,
                   const std::unordered_map<int, const TrackRow*>& predictionOf, FrameError* frames,
                   MotionSums& sums) {
  const auto succeeded = [&](int frame) -> const TrackRow* {
    const auto it = predictionOf.find(frame);
    return it != predictionOf.end() && it->second->success ? it->second : nullptr;
  };
  for (std::size_t f = 1; f < truth.rows.size(); ++f) {
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
      sums.alongMotion += (predicted->points.col(i) - now.points.col(i)).dot(truthMotion);
      sums.motionSquared += truthMotion.squaredNorm();
      ++count;
    }
    if (count == 0) continue;
    frame.jitter = sum / count;
    sums.jitterSum += frame.jitter;
    ++sums.jitterFrames;
    // The same change of the error over the face box instead of the eye distance. A truth whose
    // points span no box (fewer than two points, all in a line) gives NMJ no frame: NaN there
    // would poison the mean, so such frames count for jitter only.
    if (frame.faceSize > 1e-9) {
      frame.nmj = frame.jitter * frame.interOcular / frame.faceSize;
      sums.nmjSum += frame.nmj;
      ++sums.nmjFrames;
    }
  }
}

}  // namespace

ErrorSummary summariseFrames(const std::vector<FrameError>& frames, const Scheme& scheme,
                             const EvalOptions& options) {
  ErrorSummary s;
  s.truthFrames = static_cast<int>(frames.size());
  std::vector<double> frameErrors;
  std::vector<double> boxErrors;
  std::vector<double> allPointErrors;
  const auto& regions = scheme.regions();
  std::vector<std::vector<double>> regionErrors(regions.size());
  std::vector<int> regionTrue(regions.size(), 0);
  std::vector<int> regionFound(regions.size(), 0);

  for (const auto& frame : frames) {
    if (!frame.normalised) continue;
    ++s.normalisedFrames;
    s.predictedFrames += frame.predicted ? 1 : 0;
    s.succeededFrames += frame.success ? 1 : 0;
    s.wrongSuccesses += frame.success && frame.error > options.wrongAbove ? 1 : 0;
    s.convergedFrames += frame.converged ? 1 : 0;
    if (std::isfinite(frame.error)) {
      ++s.scoredFrames;
      frameErrors.push_back(frame.error);
      if (std::isfinite(frame.boxError)) boxErrors.push_back(frame.boxError);
    }
    for (int i = 0; i < static_cast<int>(frame.pointErrors.size()); ++i) {
      if (!frame.truePoints[static_cast<std::size_t>(i)]) continue;
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
  const auto boxStats = describe(boxErrors);
  s.meanBoxError = boxStats.mean;
  s.medianBoxError = boxStats.median;
  s.fittedShare = share(s.succeededFrames, s.normalisedFrames);

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

namespace {

// The frames of one pair (appended to `frames`, tagged with `sequence`), its motion sums and how
// many prediction rows match no truth frame. Checks as evaluateSequence documents.
int evaluatePair(const TrackPair& pair, int sequence, const Scheme& scheme,
                 const EvalOptions& options, std::vector<FrameError>& frames, MotionSums& motion) {
  const TrackTable& truth = *pair.truth;
  const TrackTable& prediction = *pair.prediction;
  const std::string& truthName = pair.truthName;
  if (truth.landmarkCount != scheme.size()) {
    throwInputError(truthName, "has " + std::to_string(truth.landmarkCount) +
                                   " landmarks (x_1..x_" + std::to_string(truth.landmarkCount) +
                                   ") but scheme " + scheme.name() + " has " +
                                   std::to_string(scheme.size()));
  }
  if (prediction.landmarkCount != truth.landmarkCount) {
    throwInputError(pair.predictionName, "has " + std::to_string(prediction.landmarkCount) +
                                             " landmarks but the ground truth " + truthName +
                                             " has " + std::to_string(truth.landmarkCount));
  }
  if (truth.rows.empty()) throwInputError(truthName, "has no frames");
  if (!options.keyColumn.empty() &&
      !trackColumnValue(truth, truth.rows.front(), options.keyColumn)) {
    std::string known;
    for (const auto& name : numericTrackColumns(truth)) known += (known.empty() ? "" : ", ") + name;
    throwInputError(truthName, "has no column \"" + options.keyColumn +
                                   "\" (its columns: " + known + ", x_k, y_k)");
  }

  std::unordered_map<int, const TrackRow*> predictionOf;
  for (const auto& row : prediction.rows) predictionOf.emplace(row.frame, &row);

  // Truth rows in frame order (tables are normally written in order; this makes sure).
  TrackTable sortedTruth = truth;
  std::stable_sort(sortedTruth.rows.begin(), sortedTruth.rows.end(),
                   [](const TrackRow& a, const TrackRow& b) { return a.frame < b.frame; });

  const std::size_t first = frames.size();
  int matched = 0;
  int normalised = 0;
  for (const auto& row : sortedTruth.rows) {
    const auto it = predictionOf.find(row.frame);
    const TrackRow* predicted = it == predictionOf.end() ? nullptr : it->second;
    matched += predicted != nullptr ? 1 : 0;
    FrameError frame = frameError(row, predicted, scheme, options);
    frame.sequence = sequence;
    if (!options.keyColumn.empty()) {
      const double key = trackColumnValue(sortedTruth, row, options.keyColumn).value_or(kNan);
      frame.key = options.keyAbsolute ? std::abs(key) : key;
    }
    normalised += frame.normalised ? 1 : 0;
    frames.push_back(std::move(frame));
  }
  measureMotion(sortedTruth, predictionOf, frames.data() + first, motion);
  if (normalised == 0) {
    const auto [a, b] = scheme.normalisationPair();
    throwInputError(truthName, "no frame has both normalisation points " + scheme.id(a) + " (" +
                                   std::to_string(a + 1) + ") and " + scheme.id(b) + " (" +
                                   std::to_string(b + 1) +
                                   ") apart, so no error can be normalised");
  }
  return static_cast<int>(prediction.rows.size()) - matched;
}

}  // namespace

SequenceEvaluation evaluateSequences(const std::vector<TrackPair>& pairs, const Scheme& scheme,
                                     const EvalOptions& options) {
  if (pairs.empty()) throw InputError("evaluation: no truth/prediction pair given");
  if (!(options.threshold > 0.0)) throw InputError("evaluation threshold must be positive");
  SequenceEvaluation result;
  MotionSums motion;
  int extraRows = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const TrackPair& pair = pairs[k];
    const int extra =
        evaluatePair(pair, static_cast<int>(k), scheme, options, result.frames, motion);
    if (extra > 0 && pairs.size() > 1) {
      throwInputError(pair.predictionName,
                      std::to_string(extra) + " of its " +
                          std::to_string(pair.prediction->rows.size()) +
                          " rows are for frames its ground truth " + pair.truthName + " (" +
                          std::to_string(pair.truth->rows.size()) +
                          " frames) does not have: is it the prediction of another sequence?");
    }
    extraRows += extra;
    result.source += (k == 0 ? "" : ", ") + pair.predictionName;
    result.sources.push_back(pair.predictionName);
  }
  result.label = result.source;
  result.summary = summariseFrames(result.frames, scheme, options);
  result.summary.extraPredictionRows = extraRows;
  if (motion.jitterFrames > 0) {
    result.summary.jitterFrames = motion.jitterFrames;
    result.summary.jitter = motion.jitterSum / motion.jitterFrames;
  }
  if (motion.nmjFrames > 0) result.summary.nmj = motion.nmjSum / motion.nmjFrames;
  if (motion.motionSquared > 1e-12) {
    result.summary.lagFrames = -motion.alongMotion / motion.motionSquared;
  }
  return result;
}

SequenceEvaluation evaluateSequence(const TrackTable& truth, const TrackTable& prediction,
                                    const Scheme& scheme, const EvalOptions& options,
                                    const std::string& truthName,
                                    const std::string& predictionName) {
  return evaluateSequences({TrackPair{&truth, &prediction, truthName, predictionName}}, scheme,
                           options);
}

std::vector<double> scoredFrameErrors(const SequenceEvaluation& evaluation) {
  std::vector<double> errors;
  for (const auto& frame : evaluation.frames) {
    if (frame.normalised && std::isfinite(frame.error)) errors.push_back(frame.error);
  }
  return errors;
}

}  // namespace clm3d
