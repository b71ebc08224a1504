// The correction loop's rules: the frames a re-track covers (up to the next keyframe, either
// way), when it stops (a failed frame, a frame agreeing with what it held before), and the
// keyboard review's next frame (failed or low confidence, not a keyframe, wrapping) and keyframe.
#include "core/track/correction_loop.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace clm3d {
namespace {

constexpr std::pair<int, int> kEyes{0, 1};

TrackRow row(int frame, bool success, double confidence, double shift = 0.0) {
  TrackRow r;
  r.frame = frame;
  r.success = success;
  r.confidence = confidence;
  r.points.resize(2, 3);
  r.points << 100 + shift, 160 + shift, 130 + shift,  // eyes 60 px apart
      100, 100, 150;
  return r;
}

GroundTruthSet setOf(std::vector<TrackRow> rows, std::vector<bool> keyframe) {
  GroundTruthSet set;
  set.table.landmarkCount = 3;
  set.table.rows = std::move(rows);
  set.keyframe = std::move(keyframe);
  return set;
}

TEST(RetrackFrames, ForwardStopsBeforeTheNextKeyframe) {
  const std::vector<bool> keyframe{false, true, false, false, false, true, false};
  EXPECT_EQ(retrackFrames(keyframe, 1, RetrackDirection::Forward), (std::vector<int>{2, 3, 4}));
  EXPECT_EQ(retrackFrames(keyframe, 5, RetrackDirection::Forward), (std::vector<int>{6}));
  EXPECT_TRUE(retrackFrames(keyframe, 6, RetrackDirection::Forward).empty());
  EXPECT_EQ(retrackFrames(keyframe, 3, RetrackDirection::Forward), (std::vector<int>{4}));
}

TEST(RetrackFrames, BackwardStopsAfterThePreviousKeyframe) {
  const std::vector<bool> keyframe{false, true, false, false, false, true, false};
  EXPECT_EQ(retrackFrames(keyframe, 5, RetrackDirection::Backward), (std::vector<int>{4, 3, 2}));
  EXPECT_EQ(retrackFrames(keyframe, 1, RetrackDirection::Backward), (std::vector<int>{0}));
  EXPECT_TRUE(retrackFrames(keyframe, 0, RetrackDirection::Backward).empty());
  EXPECT_TRUE(retrackFrames(keyframe, 7, RetrackDirection::Backward).empty());
  EXPECT_TRUE(retrackFrames(keyframe, -1, RetrackDirection::Forward).empty());
}

TEST(JudgeRetrackedRow, FailedStopsWithoutKeepingRejoinedStopsKeeping) {
  const RetrackRules rules;  // 0.02 of the eye distance: 1.2 px here
  const TrackRow before = row(3, true, 0.8);
  EXPECT_EQ(judgeRetrackedRow(row(3, false, 0.1), &before, kEyes, rules), RetrackStop::Failed);
  EXPECT_EQ(judgeRetrackedRow(row(3, true, 0.8, 1.0), &before, kEyes, rules),
            RetrackStop::Rejoined);
  EXPECT_EQ(judgeRetrackedRow(row(3, true, 0.8, 2.0), &before, kEyes, rules),
            RetrackStop::Continue);
  // A previous row the tracker had judged failed is nothing to rejoin.
  const TrackRow failed = row(3, false, 0.2);
  EXPECT_EQ(judgeRetrackedRow(row(3, true, 0.8), &failed, kEyes, rules), RetrackStop::Continue);
  EXPECT_EQ(judgeRetrackedRow(row(3, true, 0.8), nullptr, kEyes, rules), RetrackStop::Continue);
  // Tolerance 0 never stops on agreement.
  EXPECT_EQ(judgeRetrackedRow(row(3, true, 0.8), &before, kEyes, RetrackRules{0.0}),
            RetrackStop::Continue);
  // Missing points are left out of the comparison.
  TrackRow partial = row(3, true, 0.8, 0.5);
  partial.points.col(2).setConstant(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(judgeRetrackedRow(partial, &before, kEyes, rules), RetrackStop::Rejoined);
}

TEST(Review, NextFailedOrLowConfidenceFrameSkipsKeyframesAndWraps) {
  TrackRow missing = row(4, false, 0.0);
  missing.points.setConstant(std::numeric_limits<double>::quiet_NaN());
  const GroundTruthSet set = setOf({row(0, true, 0.9), row(1, false, 0.2), row(2, true, 0.3),
                                    row(3, true, 0.9), missing, row(5, false, 0.1)},
                                   {false, false, false, false, false, true});
  const ReviewRules rules{0.5};
  EXPECT_EQ(nextToReview(set, 0, 1, rules), 1);
  EXPECT_EQ(nextToReview(set, 1, 1, rules), 2);   // low confidence
  EXPECT_EQ(nextToReview(set, 2, 1, rules), 4);   // no points; 5 is a keyframe
  EXPECT_EQ(nextToReview(set, 4, 1, rules), 1);   // wraps
  EXPECT_EQ(nextToReview(set, 1, -1, rules), 4);  // wraps backwards
  EXPECT_EQ(nextToReview(set, -1, 1, rules), 1);
  EXPECT_EQ(nextToReview(set, 3, 1, ReviewRules{0.25}), 4);
  const GroundTruthSet clean = setOf({row(0, true, 0.9), row(1, false, 0.1)}, {false, false});
  EXPECT_EQ(nextToReview(clean, 1, 1, rules), -1);  // only the frame itself
  EXPECT_EQ(nextToReview(GroundTruthSet{}, 0, 1, rules), -1);
}

TEST(Review, NextKeyframeEitherWayWithoutWrapping) {
  const std::vector<bool> keyframe{true, false, false, true, false};
  EXPECT_EQ(nextKeyframe(keyframe, 0, 1), 3);
  EXPECT_EQ(nextKeyframe(keyframe, 3, 1), -1);
  EXPECT_EQ(nextKeyframe(keyframe, 3, -1), 0);
  EXPECT_EQ(nextKeyframe(keyframe, 0, -1), -1);
  EXPECT_EQ(nextKeyframe(keyframe, -1, 1), 0);
  EXPECT_EQ(nextKeyframe(keyframe, 9, -1), 3);
}

}  // namespace
}  // namespace clm3d
