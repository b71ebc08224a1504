// Re-tracking from a frame corrected by hand: forward to the end of the video (the studio's
// "re-track from here"), or over the frames the correction loop chooses (core/track/
// correction_loop.hpp: up to the next keyframe, forward or backward, stopping at a failed frame or
// where the track rejoins what the frames held), so one correction repairs the frames a lost track
// got wrong. Safe on a worker thread.
#pragma once

#include <filesystem>
#include <functional>

#include "core/common/progress.hpp"
#include "core/track/correction_loop.hpp"
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

struct SpanRetrack {
  std::vector<TrackRow> rows;                // the rows kept, in tracking order
  RetrackStop stop = RetrackStop::Continue;  // Continue: the whole span was tracked
  int stoppedAt = -1;  // the frame it stopped at (Failed: its row is not kept; Rejoined: it is)
  TrackSummary summary;
};

// Tracks `frames` (in that order, e.g. retrackFrames(...)) of `video`, starting from `state` (the
// corrected frame's) and view `view` (-1 = let the fitter choose), judging each row with
// judgeRetrackedRow against previous[frame] (the frames' rows before; shorter = none). Kept rows
// go to out.rows and perFrame sees them; the re-track stops at the first Failed or Rejoined frame.
// Progress stage "re-tracking" goes 0..1 over the frames. Throws InputError for an unreadable
// video or a frame outside it, Cancelled when cancelled (out holds the rows so far).
void retrackSpan(const std::filesystem::path& video, const ClmModel& model,
                 const TrackerSettings& settings, const FitState& state, int view,
                 const std::vector<int>& frames, const std::vector<TrackRow>& previous,
                 const RetrackRules& rules, SpanRetrack& out, const PerFrame& perFrame = {},
                 const ProgressCallback& progress = {}, const CancelToken* cancel = nullptr);

}  // namespace clm3d
