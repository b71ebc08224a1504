#include "core/track/keyframe_track.hpp"

#include <cstddef>
#include <utility>

#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"
#include "core/geometry/camera.hpp"
#include "core/video/video_reader.hpp"

namespace clm3d {

TrackSummary trackThroughKeyframes(const std::filesystem::path& video, const ClmModel& model,
                                   const TrackerSettings& settings, const GroundTruthSet& truth,
                                   const TrackRowSink& onRow, const PerFrame& perFrame,
                                   const ProgressCallback& progress, const CancelToken* cancel) {
  VideoReader reader(video);
  const Camera camera =
      Camera::fromVerticalFov(reader.width(), reader.height(), videoFovDeg(settings));
  Tracker tracker(model, camera, settings);
  const int count = truth.frameCount();
  const auto trackFrame = [&](const cv::Mat& image, int f, double timestamp,
                              TrackSummary& summary) {
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
      if (row.success) ++summary.succeeded;
      onRow(std::move(row));
      try {
        tracker.setState(stateFromPoints(model, camera, given.points, present));
      } catch (const InputError&) {
        tracker.reset();  // too few points to place the face: the next frame detects it
      }
      return;
    }
    TrackStep step = tracker.track(image, f, timestamp);
    step.row.frame = f;
    countStep(step, summary);
    if (perFrame) perFrame(image, step, tracker);
    onRow(std::move(step.row));
  };
  return trackDecodedFrames(reader, model.shape.pointCount(), trackFrame, onRow, count, "tracking",
                            progress, cancel, count);
}

std::vector<TrackRow> trackThroughKeyframes(const std::filesystem::path& video,
                                            const ClmModel& model, const TrackerSettings& settings,
                                            const GroundTruthSet& truth,
                                            const ProgressCallback& progress,
                                            const CancelToken* cancel, TrackSummary* summary) {
  std::vector<TrackRow> rows;
  rows.reserve(static_cast<std::size_t>(truth.frameCount()));
  const TrackSummary made = trackThroughKeyframes(
      video, model, settings, truth, [&rows](TrackRow&& row) { rows.push_back(std::move(row)); },
      {}, progress, cancel);
  if (summary) *summary = made;
  return rows;
}

}  // namespace clm3d
