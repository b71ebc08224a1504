// Re-tracking forward from a frame corrected by hand (the studio's "re-track from here"): the
// tracker starts from the corrected state on the frame after it and follows the rest of the video,
// so one correction repairs the frames a lost track got wrong. Safe on a worker thread.
#pragma once

#include <filesystem>
#include <functional>

#include "core/common/progress.hpp"
#include "core/track/tracker.hpp"

namespace clm3d {

// Tracks frames corrected+1 .. end of `video` (or until cancelled), starting from `state` (the
// corrected frame's FitState, e.g. stateFromPoints of the corrected points) and view `view`
// (-1 = let the fitter choose). Rows are appended to `rows` in frame order; perFrame sees each
// frame with its step. Progress stage "re-tracking" goes 0..1 over the remaining frames. Throws
// InputError for an unreadable video or a frame index outside it, Cancelled when cancelled (the
// rows so far stay in `rows`).
TrackSummary retrackFrom(
    const std::filesystem::path& video, const ClmModel& model, const TrackerSettings& settings,
    int corrected, const FitState& state, int view, std::vector<TrackRow>& rows,
    const std::function<void(const cv::Mat&, const TrackStep&, Tracker&)>& perFrame = {},
    const ProgressCallback& progress = {}, const CancelToken* cancel = nullptr);

}  // namespace clm3d
