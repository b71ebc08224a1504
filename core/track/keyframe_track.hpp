// Tracking a video through the keyframes of its ground truth: each keyframe's points are taken as
// they are and the tracker goes on from them (the pose and shape that best reproduce them, as the
// studio's correction loop starts a re-track), every other frame is tracked; frames before the
// first keyframe start from a detection, as `clm3d track` does. How the studio's Adapt and issue
// 29's correction benchmark re-track the frames nobody corrected with an adapted model (core/eval/
// detail/correction_benchmark.hpp), and, without keyframes, the benchmark's first track of a
// sequence. The frames are decoded as `clm3d track` decodes them (trackDecodedFrames): a frame the
// video declares but cannot give is a row marked unreadable in its place, so that every later row
// stays on its own frame's truth. Safe on a worker thread.
#pragma once

#include <filesystem>
#include <vector>

#include "core/common/progress.hpp"
#include "core/track/ground_truth.hpp"
#include "core/track/tracker.hpp"

namespace clm3d {

// Frames 0 .. truth.frameCount() - 1 of `video` (fewer if the video ends first), each row handed
// to `onRow` in frame order: a keyframe with points keeps its row and restarts the tracker from
// it; every other frame is tracked with `model` and shown to `perFrame`; an undecodable frame is
// an unreadable row (TrackSummary::unreadable). Progress stage "tracking" goes 0..1 over the
// frames. InputError for an unreadable video; Cancelled when cancelled (the rows so far handed on).
TrackSummary trackThroughKeyframes(const std::filesystem::path& video, const ClmModel& model,
                                   const TrackerSettings& settings, const GroundTruthSet& truth,
                                   const TrackRowSink& onRow, const PerFrame& perFrame = {},
                                   const ProgressCallback& progress = {},
                                   const CancelToken* cancel = nullptr);
// The same, the rows returned; `summary`, when given, gets the run's summary.
std::vector<TrackRow> trackThroughKeyframes(const std::filesystem::path& video,
                                            const ClmModel& model, const TrackerSettings& settings,
                                            const GroundTruthSet& truth,
                                            const ProgressCallback& progress = {},
                                            const CancelToken* cancel = nullptr,
                                            TrackSummary* summary = nullptr);

}  // namespace clm3d
