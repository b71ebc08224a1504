#include "core/track/keyframe_track.hpp"

#include <cstddef>
#include <utility>

#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"
#include "core/geometry/camera.hpp"
#include "core/video/video_reader.hpp"

namespace clm3d {

std::vector<TrackRow> trackThroughKeyframes(const std::filesystem::path& video,
                                            const ClmModel& model, const TrackerSettings& settings,
                                            const GroundTruthSet& truth,
                                            const ProgressCallback& progress,
                                            const CancelToken* cancel) {
  VideoReader reader(video);
  const Camera camera =
      Camera::fromVerticalFov(reader.width(), reader.height(), kDefaultVerticalFovDeg);
  Tracker tracker(model, camera, settings);
  const int count = truth.frameCount();
  std::vector<TrackRow> rows;
  rows.reserve(static_cast<std::size_t>(count));
  cv::Mat frame;
  while (std::cmp_less(rows.size(), count) && reader.read(frame)) {
    if (cancel != nullptr) cancel->throwIfCancelled();
    const int f = static_cast<int>(rows.size());
    const auto i = static_cast<std::size_t>(f);
    const TrackRow& given = truth.table.rows[i];
    std::vector<bool> present(static_cast<std::size_t>(given.points.cols()));
    int presentCount = 0;
    for (int k = 0; k < given.points.cols(); ++k) {
      present[static_cast<std::size_t>(k)] = given.points.col(k).allFinite();
      presentCount += present[static_cast<std::size_t>(k)] ? 1 : 0;
    }
    if (truth.keyframe[i] && presentCount > 0) {
      TrackRow row = given;
      row.frame = f;
      rows.push_back(std::move(row));
      try {
        tracker.setState(stateFromPoints(model, camera, given.points, present));
      } catch (const InputError&) {
        tracker.reset();  // too few points to place the face: the next frame detects it
      }
    } else {
      TrackStep step = tracker.track(frame, f, reader.timestamp());
      step.row.frame = f;
      rows.push_back(std::move(step.row));
    }
    if (progress && count > 0) progress(static_cast<double>(f + 1) / count, "tracking");
  }
  if (progress) progress(1.0, "tracking");
  return rows;
}

}  // namespace clm3d
