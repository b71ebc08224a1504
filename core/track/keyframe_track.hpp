// Tracking a video through the keyframes of its ground truth: each keyframe's points are taken as
// they are and the tracker goes on from them (the pose and shape that best reproduce them, as the
// studio's correction loop starts a re-track), every other frame is tracked; frames before the
// first keyframe start from a detection, as `clm3d track` does. How issue 29's correction
// benchmark re-tracks the frames nobody corrected with an adapted model (core/eval/
// correction_benchmark.hpp), and, without keyframes, its first track of a sequence's frames.
// Safe on a worker thread.
#pragma once

#include <filesystem>
#include <vector>

#include "core/common/progress.hpp"
#include "core/track/ground_truth.hpp"
#include "core/track/tracker.hpp"

namespace clm3d {

// The rows of frames 0 .. truth.frameCount() - 1 of `video` (fewer if the video ends first), in
// frame order: a keyframe with points keeps its row and restarts the tracker from it; every other
// frame is tracked with `model`. Progress stage "tracking" goes 0..1 over the frames. InputError
// for an unreadable video; Cancelled when cancelled.
std::vector<TrackRow> trackThroughKeyframes(const std::filesystem::path& video,
                                            const ClmModel& model, const TrackerSettings& settings,
                                            const GroundTruthSet& truth,
                                            const ProgressCallback& progress = {},
                                            const CancelToken* cancel = nullptr);

}  // namespace clm3d
