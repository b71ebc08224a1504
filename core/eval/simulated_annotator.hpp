// The simulated annotator of issue 29's correction benchmark: a person cleaning a track against a
// known truth, one frame at a time, until every frame is within a share of the eye distance of the
// truth (eq. 5.1), under three strategies:
//   in-order      the studio's loop as it was: walk the frames in order and correct the first
//                 wrong one;
//   review        pick the highest-ranked frame of the review list (core/track/review_list.hpp,
//                 ranked anew after every correction) that is wrong; when the list offers none,
//                 the first wrong frame in order (a fallback, counted);
//   review-adapt  review, and after every N corrections the general model adapted to the
//                 corrected frames and the frames not corrected re-tracked with it.
// A correction sets the frame to its truth (a keyframe); every point farther than a share of the
// eye distance from its truth is one drag. After each correction the tracker re-tracks forward by
// the studio's rules (core/track/correction_loop.hpp: up to the next keyframe, stopping at a
// failed frame or where it rejoins the frames' previous rows). The tracker is an interface, so the
// rules are tested without a video; core/eval/detail/correction_benchmark.hpp gives the real one.
// docs/studio-track.md describes the benchmark.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/scheme/scheme.hpp"
#include "core/track/correction_loop.hpp"
#include "core/track/ground_truth.hpp"
#include "core/track/retrack.hpp"
#include "core/track/review_list.hpp"

namespace clm3d {

enum class AnnotatorStrategy { InOrder, Review, ReviewAdapt };
// "in-order", "review", "review-adapt".
const char* annotatorStrategyName(AnnotatorStrategy strategy);
// The strategy of that name; InputError listing the names otherwise.
AnnotatorStrategy annotatorStrategyByName(const std::string& name);

struct AnnotatorSettings {
  // A frame is right when its error (eq. 5.1: mean point distance over the true eye distance) is
  // at most this; a frame whose truth has eye points and whose track has no point in common with
  // it is wrong.
  double tolerance = 0.05;
  // A point farther than this share of the true eye distance from its truth (or missing where the
  // truth has it) is one drag when its frame is corrected.
  double dragTolerance = 0.05;
  int adaptEvery = 5;        // review-adapt: adapt after every this many corrections
  int maxCorrections = 300;  // the run stops after this many (capped), so it always ends
  ReviewListSettings review;
  RetrackRules retrack;

  // InputError naming the setting out of range.
  void validate() const;
};

// What the annotator asks of a tracker.
class AnnotatorTracker {
 public:
  virtual ~AnnotatorTracker() = default;
  // The loop's re-track after frame `corrected` was set to `points` (NaN columns: missing):
  // `frames` (retrackFrames, forward) from the state those points give, judged against
  // `previous` (the frames' rows before) with `rules`, as retrackSpan does.
  virtual SpanRetrack retrack(int corrected, const Eigen::Matrix2Xd& points,
                              const std::vector<int>& frames, const std::vector<TrackRow>& previous,
                              const RetrackRules& rules) = 0;
  // Adapts the general model to the keyframes of `truth`, tracks with the adapted model from now
  // on (retrack too), and returns its rows of every frame of `truth` (frame order; a keyframe's
  // row is not used).
  virtual std::vector<TrackRow> adapt(const GroundTruthSet& truth) = 0;
};

struct AnnotatorRun {
  AnnotatorStrategy strategy = AnnotatorStrategy::InOrder;
  int scoredFrames = 0;     // frames whose truth has the eye points (the others are never wrong)
  int wrongAtStart = 0;     // of those, wrong in the track given
  int corrected = 0;        // frames corrected
  int drags = 0;            // points dragged over all corrections
  int fallbacks = 0;        // review strategies: corrections picked in frame order
  int adaptations = 0;      // review-adapt: adaptations run
  int retracks = 0;         // re-tracks that kept at least one row
  int retrackedFrames = 0;  // rows those re-tracks replaced
  int wrongAtEnd = 0;       // frames still wrong when the run ended
  bool capped = false;      // stopped by maxCorrections with frames still wrong
  std::vector<int> correctedFrames;  // in the order corrected
  GroundTruthSet result;             // the ground truth at the end: corrected frames are keyframes
};

// Runs one strategy on one sequence: `truth` (row per frame 0..n-1; rows without points are never
// wrong) and `track` (the tracker's first pass; row per frame, same landmarks), scored with
// `scheme` (eq. 5.1 through evaluateSequence). Progress after each correction: the share of the
// frames wrong at the start that are right now, stage "STRATEGY: N corrected, W wrong". InputError
// when the tables do not match (landmark counts, a truth row that is not its frame) or the
// settings are out of range; Cancelled when cancelled.
AnnotatorRun simulateAnnotator(AnnotatorStrategy strategy, const TrackTable& truth,
                               const TrackTable& track, const Scheme& scheme,
                               AnnotatorTracker& tracker, const AnnotatorSettings& settings = {},
                               const ProgressCallback& progress = {},
                               const CancelToken* cancel = nullptr);

}  // namespace clm3d
