#include "core/track/correction_loop.hpp"

#include <algorithm>
#include <cmath>

namespace clm3d {

std::vector<int> retrackFrames(const std::vector<bool>& keyframe, int corrected,
                               RetrackDirection direction) {
  std::vector<int> frames;
  const int count = static_cast<int>(keyframe.size());
  if (corrected < 0 || corrected >= count) return frames;
  const int step = direction == RetrackDirection::Forward ? 1 : -1;
  for (int f = corrected + step; f >= 0 && f < count; f += step) {
    if (keyframe[static_cast<std::size_t>(f)]) break;
    frames.push_back(f);
  }
  return frames;
}

RetrackStop judgeRetrackedRow(const TrackRow& fresh, const TrackRow* previous,
                              std::pair<int, int> eyes, const RetrackRules& rules) {
  if (!fresh.success) return RetrackStop::Failed;
  if (previous == nullptr || !previous->success || rules.rejoinTolerance <= 0.0 ||
      previous->points.cols() != fresh.points.cols()) {
    return RetrackStop::Continue;
  }
  const auto [a, b] = eyes;
  if (a < 0 || b < 0 || a >= fresh.points.cols() || b >= fresh.points.cols()) {
    return RetrackStop::Continue;
  }
  const double eyeDistance = (previous->points.col(a) - previous->points.col(b)).norm();
  if (!std::isfinite(eyeDistance) || eyeDistance <= 0.0) return RetrackStop::Continue;
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < fresh.points.cols(); ++i) {
    if (!fresh.points.col(i).allFinite() || !previous->points.col(i).allFinite()) continue;
    sum += (fresh.points.col(i) - previous->points.col(i)).norm();
    ++count;
  }
  if (count == 0) return RetrackStop::Continue;
  return sum / count <= rules.rejoinTolerance * eyeDistance ? RetrackStop::Rejoined
                                                            : RetrackStop::Continue;
}

bool needsReview(const TrackRow& row, bool keyframe, const ReviewRules& rules) {
  if (keyframe) return false;
  bool anyPoint = false;
  for (int i = 0; i < row.points.cols() && !anyPoint; ++i) anyPoint = row.points.col(i).allFinite();
  return !anyPoint || !row.success || !(row.confidence >= rules.lowConfidence);
}

int nextToReview(const GroundTruthSet& truth, int from, int step, const ReviewRules& rules) {
  const int count = truth.frameCount();
  if (count == 0 || (step != 1 && step != -1)) return -1;
  for (int k = 1; k <= count; ++k) {
    const int f = ((from + step * k) % count + count) % count;
    if (f == from) continue;
    const auto i = static_cast<std::size_t>(f);
    if (needsReview(truth.table.rows[i], truth.keyframe[i], rules)) return f;
  }
  return -1;
}

int nextKeyframe(const std::vector<bool>& keyframe, int from, int step) {
  const int count = static_cast<int>(keyframe.size());
  if (step != 1 && step != -1) return -1;
  const int first = step > 0 ? std::max(from + 1, 0) : std::min(from - 1, count - 1);
  for (int f = first; f >= 0 && f < count; f += step) {
    if (keyframe[static_cast<std::size_t>(f)]) return f;
  }
  return -1;
}

}  // namespace clm3d
