#include "core/track/retrack.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "core/common/error.hpp"
#include "core/geometry/camera.hpp"
#include "core/video/video_reader.hpp"

namespace clm3d {

TrackSummary retrackFrom(
    const std::filesystem::path& video, const ClmModel& model, const TrackerSettings& settings,
    int corrected, const FitState& state, int view, std::vector<TrackRow>& rows,
    const std::function<void(const cv::Mat&, const TrackStep&, Tracker&)>& perFrame,
    const ProgressCallback& progress, const CancelToken* cancel) {
  VideoReader reader(video);
  const int total = reader.frameCount();
  if (corrected < 0 || (total > 0 && corrected >= total)) {
    throw InputError(video.string() + ": frame " + std::to_string(corrected) +
                     " is not in the video (" + std::to_string(total) + " frames)");
  }
  TrackSummary summary;
  // The corrected frame is the last one; nothing follows it.
  if (!reader.seek(corrected + 1)) {
    if (progress) progress(1.0, "re-tracking");
    return summary;
  }
  const Camera camera =
      Camera::fromVerticalFov(reader.width(), reader.height(), videoFovDeg(settings));
  Tracker tracker(model, camera, settings);
  tracker.setState(state, view);
  const int remaining = total > 0 ? total - corrected - 1 : 0;
  return trackRemainingFrames(reader, tracker, rows, remaining, "re-tracking", perFrame, progress,
                              cancel);
}

void retrackSpan(const std::filesystem::path& video, const ClmModel& model,
                 const TrackerSettings& settings, const FitState& state, int view,
                 const std::vector<int>& frames, const std::vector<TrackRow>& previous,
                 const RetrackRules& rules, SpanRetrack& out, const PerFrame& perFrame,
                 const ProgressCallback& progress, const CancelToken* cancel) {
  VideoReader reader(video);
  const int total = reader.frameCount();
  for (const int f : frames) {
    if (f < 0 || (total > 0 && f >= total)) {
      throw InputError(video.string() + ": frame " + std::to_string(f) + " is not in the video (" +
                       std::to_string(total) + " frames)");
    }
  }
  const Camera camera =
      Camera::fromVerticalFov(reader.width(), reader.height(), videoFovDeg(settings));
  Tracker tracker(model, camera, settings);
  tracker.setState(state, view);
  const std::pair<int, int> eyes = model.scheme().normalisationPair();
  cv::Mat frame;
  int done = 0;
  for (const int f : frames) {
    if (cancel != nullptr) cancel->throwIfCancelled();
    // Forward the reader reads on; backward (or after a gap) it seeks.
    if (reader.frameIndex() != f - 1 && !reader.seek(f)) break;
    if (!reader.read(frame)) break;
    TrackStep step = tracker.track(frame, reader.frameIndex(), reader.timestamp());
    ++out.summary.frames;
    if (step.row.success) ++out.summary.succeeded;
    if (step.detected) ++out.summary.detections;
    if (step.fit) out.summary.fitMilliseconds.push_back(step.fitMilliseconds);
    const TrackRow* before =
        std::cmp_less(f, previous.size()) ? &previous[static_cast<std::size_t>(f)] : nullptr;
    const RetrackStop verdict = judgeRetrackedRow(step.row, before, eyes, rules);
    if (verdict != RetrackStop::Failed) {
      if (perFrame) perFrame(frame, step, tracker);
      out.rows.push_back(std::move(step.row));
    }
    ++done;
    if (progress)
      progress(static_cast<double>(done) / static_cast<double>(frames.size()), "re-tracking");
    if (verdict != RetrackStop::Continue) {
      out.stop = verdict;
      out.stoppedAt = f;
      break;
    }
  }
  if (progress) progress(1.0, "re-tracking");
}

}  // namespace clm3d
