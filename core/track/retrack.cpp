#include "core/track/retrack.hpp"

#include <algorithm>
#include <string>

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
      Camera::fromVerticalFov(reader.width(), reader.height(), kDefaultVerticalFovDeg);
  Tracker tracker(model, camera, settings);
  tracker.setState(state, view);
  const int remaining = total > 0 ? total - corrected - 1 : 0;
  return trackRemainingFrames(reader, tracker, rows, remaining, "re-tracking", perFrame, progress,
                              cancel);
}

}  // namespace clm3d
