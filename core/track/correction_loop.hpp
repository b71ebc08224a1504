// The rules of the studio's correction loop, without any widget, so they are tested on their own:
// which frames a re-track from a corrected frame covers (up to the next keyframe, forward or
// backward), when a re-track stops (a failed frame; a frame where it agrees with what the frame
// held before, so going on would only repeat it), and which frame the keyboard review goes to next
// (the next failed or low-confidence frame that is not a keyframe, the next keyframe).
// docs/studio-track.md describes the loop.
#pragma once

#include <utility>
#include <vector>

#include "core/track/ground_truth.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

enum class RetrackDirection { Forward, Backward };

// The frames a re-track from `corrected` tracks, in tracking order: forward corrected+1 up to the
// frame before the next keyframe (or the last frame), backward corrected-1 down to the frame after
// the previous keyframe (or frame 0). `keyframe` has one entry per frame; empty when there is no
// such frame (or `corrected` is outside the video).
std::vector<int> retrackFrames(const std::vector<bool>& keyframe, int corrected,
                               RetrackDirection direction);

struct RetrackRules {
  // A re-tracked frame whose points are within this share of the eye distance (mean point
  // distance, eq. 5.1) of the frame's previous points, when those were a successful fit or set by
  // hand, ends the re-track there: the tracker has rejoined the track it had. 0 never stops so.
  double rejoinTolerance = 0.02;
};

enum class RetrackStop {
  Continue,  // keep the row and go on
  Rejoined,  // keep the row and stop: it agrees with the frame's previous row
  Failed,    // the tracker judged the frame failed: do not keep the row, stop
};

// What the loop does with a freshly re-tracked row. `previous` is the frame's row before the
// re-track (nullptr if it had none); `eyes` the scheme's normalisation pair (points 8 and 11).
RetrackStop judgeRetrackedRow(const TrackRow& fresh, const TrackRow* previous,
                              std::pair<int, int> eyes, const RetrackRules& rules);

struct ReviewRules {
  // A frame whose confidence is below this needs a look (on the tracker's confidence scale: NCC
  // for the template optimisers, the experts' response for rlms).
  double lowConfidence = 0.5;
};

// A frame needs review when it is not a keyframe and it has no points, or the tracker judged it
// failed, or its confidence is below the rule's.
bool needsReview(const TrackRow& row, bool keyframe, const ReviewRules& rules);

// The next frame after `from` (step +1) or before it (step -1) that needs review, wrapping around
// the ends of the video; -1 when no frame (other than `from`) needs review.
int nextToReview(const GroundTruthSet& truth, int from, int step, const ReviewRules& rules);

// The next keyframe after `from` (step +1) or before it (step -1), without wrapping; -1 if none.
int nextKeyframe(const std::vector<bool>& keyframe, int from, int step);

}  // namespace clm3d
