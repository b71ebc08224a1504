// The page's long operations as JobRunner jobs, each working on copies of what it needs and
// filling an outcome the page takes over on the GUI thread when the job has ended: tracking the
// whole video (loading the model first if needed), re-tracking forward from a corrected frame, and
// writing the overlay video. A cancelled track or re-track keeps the frames done so far. Tracking
// follows the settings' faces (TrackerSettings::faces) as `clm3d track --faces` does; a re-track
// follows the one face it starts from.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/review/track_session.hpp"
#include "core/track/retrack.hpp"
#include "core/track/tracker.hpp"
#include "core/train/model_adaptation.hpp"
#include "ui/common/job_runner.hpp"

namespace clm3d::ui {

struct TrackOutcome {
  std::shared_ptr<const ClmModel> model;  // loaded by the job when none was given
  // Face by face (settings.faces != 1): the rows of every face with a `face` column, as `clm3d
  // track --faces` writes them, and the fits per face id indexed by frame.
  TrackTable table;
  std::vector<std::optional<FrameFit>> fits;  // one face: per frame of table.rows
  std::map<int, std::vector<std::optional<FrameFit>>> faceFits;
  TrackSummary summary;
  std::string warning;  // unreadableFramesWarning: frames the video declares but could not give
};

// Tracks every frame of `video`; `model` may be null, then the job loads `modelPath`.
JobRunner::Job trackJob(std::filesystem::path video, std::filesystem::path modelPath,
                        std::shared_ptr<const ClmModel> model, TrackerSettings settings,
                        std::shared_ptr<TrackOutcome> outcome);

struct RetrackOutcome {
  int face = 0;  // the face re-tracked (TrackSession::selectedFace when started)
  int corrected = 0;
  std::vector<TrackRow> rows;  // frames corrected+1 onwards
  std::vector<std::optional<FrameFit>> fits;
};

// Starts from the state that best reproduces `points` (the corrected frame's, NaN = missing).
JobRunner::Job retrackJob(std::filesystem::path video, std::shared_ptr<const ClmModel> model,
                          TrackerSettings settings, int corrected, Eigen::Matrix2Xd points,
                          std::shared_ptr<RetrackOutcome> outcome);

struct LoopOutcome {
  int face = 0;  // the face re-tracked (TrackSession::selectedFace when started)
  int corrected = 0;
  RetrackDirection direction = RetrackDirection::Forward;
  Eigen::Matrix2Xd points;                    // the corrected frame's points the job started from
  std::shared_ptr<const ClmModel> model;      // loaded by the job when none was given
  SpanRetrack retrack;                        // rows in tracking order
  std::vector<std::optional<FrameFit>> fits;  // per row of retrack.rows
};

// The correction loop's re-track (core retrackSpan) of `frames`, from the state that best
// reproduces `points` (the corrected frame's), judged against `previous` (the frames' rows before).
// `model` may be null, then the job loads `modelPath`.
JobRunner::Job loopRetrackJob(std::filesystem::path video, std::filesystem::path modelPath,
                              std::shared_ptr<const ClmModel> model, TrackerSettings settings,
                              std::vector<int> frames, std::vector<TrackRow> previous,
                              RetrackRules rules, std::shared_ptr<LoopOutcome> outcome);

struct AdaptOutcome {
  std::shared_ptr<const ClmModel> model;  // the adapted model
  std::filesystem::path saved;            // where it was written: empty unless the job finished
  AdaptationSummary summary;
  TrackTable
      table;  // every frame: the keyframes as given, the others tracked with the adapted model
  std::vector<std::optional<FrameFit>> fits;
};

// Adapts the model (`model`, or when null the one loaded from `modelPath`) to the keyframes of
// `truth` (core/track/video_adaptation; `truthPath` is recorded as where they came from), tracks
// `video` through those keyframes with the adapted model (trackThroughKeyframes: each corrected
// frame restarts the track from its points), and only then writes it to `out` (atomically): a
// cancelled or failed job writes nothing.
JobRunner::Job adaptJob(std::filesystem::path video, std::filesystem::path modelPath,
                        std::shared_ptr<const ClmModel> model, GroundTruthSet truth,
                        std::filesystem::path truthPath, AdaptSettings adapt,
                        TrackerSettings settings, std::filesystem::path out,
                        std::shared_ptr<AdaptOutcome> outcome);

// Writes `out` (.mp4/.avi/.mkv) with every frame drawn by drawReviewOverlay: `shown` are the rows
// to draw (the ground truth: one per frame, or one per face and frame when face by face; each row
// on the frame it names), `fits` their stored fit states (parallel to `shown`).
JobRunner::Job exportOverlayJob(std::filesystem::path video, std::filesystem::path out,
                                std::shared_ptr<const ClmModel> model, std::vector<TrackRow> shown,
                                std::vector<std::optional<FrameFit>> fits, bool patches);

}  // namespace clm3d::ui
