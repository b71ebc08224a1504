// The frames of a track worth a look, ranked, each with why it was picked: the way DeepLabCut
// extracts outlier frames, by three criteria: (a) a low check (the tracks CSV's confidence below a
// threshold, or a failed frame), (b) a point that jumps more than a share of the eye distance from
// the previous frame, (c) a point far from a smooth fit of its path over time (a moving median of
// each coordinate over a centred window: robust to the outlier itself, and it keeps a real step,
// which a polynomial would smear into its neighbours). `clm3d review` writes the list as CSV; the
// studio's Track page marks it on the timeline and walks it with N / Shift+N. Keyframes (frames a
// person accepted or corrected) are never listed. docs/studio-track.md describes the rules.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/common/option_table.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

struct ReviewListSettings {
  // (a) A frame whose confidence is below this is listed (the tracker's scale: the view's check
  // probability, NCC for the template optimisers, the experts' response for rlms).
  double lowConfidence = 0.5;
  // (b) A point moving more than this share of the eye distance from the previous frame.
  double jump = 0.15;
  // (c) A point farther than this share of the eye distance from its moving median.
  double fitDistance = 0.1;
  // (c) Frames in the moving median's window, centred on the frame (odd).
  int window = 9;
  // Keep the best this many (0: every listed frame).
  int maxFrames = 0;
};

// The option table of those settings: `clm3d review`'s options and the studio's names for them.
const std::vector<Option<ReviewListSettings>>& reviewListOptions();

enum class ReviewCriterion { Failed, LowConfidence, Jump, TemporalFit };
// "failed", "low-confidence", "jump", "temporal-fit": the list's spelling.
const char* reviewCriterionName(ReviewCriterion criterion);

struct ReviewReason {
  ReviewCriterion criterion = ReviewCriterion::Failed;
  // Failed / LowConfidence: the confidence (NaN if the row has none); Jump / TemporalFit: the
  // largest distance over points, in eye distances.
  double value = 0.0;
  int point = -1;  // Jump / TemporalFit: the 0-based landmark that moved most; -1 otherwise
  // How far past its threshold: value / threshold for a distance, (1 - c) / (1 - threshold) for a
  // confidence c; infinite for a failed frame (no usable points: always first). Above 1 when
  // listed.
  double severity = 0.0;
};

struct ReviewItem {
  int frame = 0;
  double score = 0.0;                 // the strongest reason's severity: the rank order
  std::vector<ReviewReason> reasons;  // every criterion that picked the frame, strongest first
};

// The frames `table` (row per frame, any order) gives reason to look at, most severe first (ties:
// earlier frame first). `keyframe[frame]` true (where the vector reaches) leaves the frame out.
// `eyes` is the scheme's normalisation pair; the eye distance of a frame is the median of the eye
// distances over its window (so one broken frame does not rescale itself). Jumps are measured from
// the previous frame when both have the point; the moving median needs 3 frames with the point.
// InputError for settings out of range or an eye index outside the table's landmarks.
std::vector<ReviewItem> rankFramesForReview(const TrackTable& table,
                                            const std::vector<bool>& keyframe,
                                            std::pair<int, int> eyes,
                                            const ReviewListSettings& settings = {});

// The list as CSV: rank, frame, score, criterion, value, point (1-based, empty if none) of the
// strongest reason, then `reasons` ("jump=0.231@12;temporal-fit=0.18@12;low-confidence=0.31").
std::string formatReviewList(const std::vector<ReviewItem>& items);
void writeReviewList(const std::filesystem::path& csv, const std::vector<ReviewItem>& items);

}  // namespace clm3d
