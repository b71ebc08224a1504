// The frames worth a look: each criterion on its own (a low check, a jump, an outlier against the
// moving median), a smooth track listing nothing, a step that is a jump but not an outlier,
// keyframes left out, failed frames first, the rank order across criteria, the cap, the CSV and
// the errors for bad settings and eye points.
#include "core/track/review_list.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/common/error.hpp"
#include "core/common/number_text.hpp"

namespace clm3d {
namespace {

constexpr std::pair<int, int> kReviewEyes{7, 10};  // thesis25's eye centres
constexpr double kReviewEyeDistance = 60.0;        // their distance, pixels

// 60 frames of 25 points swaying smoothly (20 pixels, a 60-frame period: at most 0.035 eye
// distances a frame), confidence 0.8.
TrackTable smoothReviewTrack() {
  TrackTable table;
  table.landmarkCount = 25;
  for (int f = 0; f < 60; ++f) {
    TrackRow row;
    row.frame = f;
    row.timestamp = f / 30.0;
    row.success = true;
    row.confidence = 0.8;
    const double sway = 20.0 * std::sin(2.0 * std::numbers::pi * f / 60.0);
    row.points.resize(2, 25);
    for (int i = 0; i < 25; ++i) row.points.col(i) = Eigen::Vector2d(200.0 + 5.0 * i + sway, 300.0);
    row.points.col(7) = Eigen::Vector2d(220.0 + sway, 250.0);
    row.points.col(10) = Eigen::Vector2d(220.0 + kReviewEyeDistance + sway, 250.0);
    table.rows.push_back(row);
  }
  return table;
}

TEST(ReviewList, SmoothTrackListsNothing) {
  EXPECT_TRUE(rankFramesForReview(smoothReviewTrack(), {}, kReviewEyes).empty());
}

TEST(ReviewList, LowCheckIsListed) {
  TrackTable track = smoothReviewTrack();
  track.rows[10].confidence = 0.3;
  const auto items = rankFramesForReview(track, {}, kReviewEyes);
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items[0].frame, 10);
  ASSERT_EQ(items[0].reasons.size(), 1u);
  EXPECT_EQ(items[0].reasons[0].criterion, ReviewCriterion::LowConfidence);
  EXPECT_DOUBLE_EQ(items[0].reasons[0].value, 0.3);
  EXPECT_NEAR(items[0].score, 0.7 / 0.5, 1e-12);
  // The threshold is the setting's.
  ReviewListSettings lenient;
  lenient.lowConfidence = 0.2;
  EXPECT_TRUE(rankFramesForReview(track, {}, kReviewEyes, lenient).empty());
}

// A step (the head moves 0.3 eye distances between frames 29 and 30, then stays) is a jump at
// frame 30 only; the moving median follows the step, so no frame is an outlier against it.
TEST(ReviewList, JumpIsListedAndAStepIsNoOutlier) {
  TrackTable track = smoothReviewTrack();
  for (int f = 30; f < 60; ++f)
    track.rows[static_cast<std::size_t>(f)].points.row(1).array() += 18.0;
  const auto items = rankFramesForReview(track, {}, kReviewEyes);
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items[0].frame, 30);
  ASSERT_EQ(items[0].reasons.size(), 1u);
  EXPECT_EQ(items[0].reasons[0].criterion, ReviewCriterion::Jump);
  EXPECT_NEAR(items[0].reasons[0].value, 0.3, 0.04);  // the step plus a frame's sway
  EXPECT_GE(items[0].reasons[0].point, 0);
  ReviewListSettings lenient;
  lenient.jump = 0.4;
  EXPECT_TRUE(rankFramesForReview(track, {}, kReviewEyes, lenient).empty());
}

// One point off by 0.12 eye distances on one frame: below the jump threshold both ways, but far
// from the point's moving median.
TEST(ReviewList, OutlierAgainstTheTemporalFitIsListed) {
  TrackTable track = smoothReviewTrack();
  track.rows[40].points(1, 11) += 0.12 * kReviewEyeDistance;
  const auto items = rankFramesForReview(track, {}, kReviewEyes);
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items[0].frame, 40);
  ASSERT_EQ(items[0].reasons.size(), 1u);
  EXPECT_EQ(items[0].reasons[0].criterion, ReviewCriterion::TemporalFit);
  EXPECT_EQ(items[0].reasons[0].point, 11);
  EXPECT_NEAR(items[0].reasons[0].value, 0.12, 0.005);
  EXPECT_NEAR(items[0].score, 1.2, 0.05);
  ReviewListSettings lenient;
  lenient.fitDistance = 0.15;
  EXPECT_TRUE(rankFramesForReview(track, {}, kReviewEyes, lenient).empty());
}

TEST(ReviewList, RanksAcrossCriteriaLeavesKeyframesOutAndCaps) {
  TrackTable track = smoothReviewTrack();
  track.rows[10].confidence = 0.3;  // severity 1.4
  for (int f = 30; f < 60; ++f)
    track.rows[static_cast<std::size_t>(f)].points.row(1).array() += 18.0;
  track.rows[45].points(1, 11) += 0.12 * kReviewEyeDistance;  // about 1.2
  track.rows[50].success = false;                             // failed: first
  track.rows[50].points.setConstant(kNan);
  const auto items = rankFramesForReview(track, {}, kReviewEyes);
  ASSERT_EQ(items.size(), 4u);
  EXPECT_EQ(items[0].frame, 50);
  EXPECT_EQ(items[0].reasons[0].criterion, ReviewCriterion::Failed);
  EXPECT_EQ(items[1].frame, 30);
  EXPECT_EQ(items[2].frame, 10);
  EXPECT_EQ(items[3].frame, 45);
  for (std::size_t i = 1; i < items.size(); ++i) EXPECT_GE(items[i - 1].score, items[i].score);

  std::vector<bool> keyframe(60, false);
  keyframe[30] = true;
  keyframe[50] = true;
  const auto left = rankFramesForReview(track, keyframe, kReviewEyes);
  ASSERT_EQ(left.size(), 2u);
  EXPECT_EQ(left[0].frame, 10);
  EXPECT_EQ(left[1].frame, 45);

  ReviewListSettings capped;
  capped.maxFrames = 2;
  const auto top = rankFramesForReview(track, {}, kReviewEyes, capped);
  ASSERT_EQ(top.size(), 2u);
  EXPECT_EQ(top[1].frame, 30);

  const std::string csv = formatReviewList(top);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "rank,frame,score,criterion,value,point,reasons");
  EXPECT_NE(csv.find("\n1,50,inf,failed,0.8,,failed=0.8\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n2,30,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",jump,"), std::string::npos) << csv;
}

TEST(ReviewList, BadSettingsAndEyesAreErrors) {
  ReviewListSettings bad;
  bad.window = 1;
  EXPECT_THROW(rankFramesForReview(smoothReviewTrack(), {}, kReviewEyes, bad), InputError);
  bad = {};
  bad.lowConfidence = 1.0;  // would divide by zero
  EXPECT_THROW(rankFramesForReview(smoothReviewTrack(), {}, kReviewEyes, bad), InputError);
  EXPECT_THROW(rankFramesForReview(smoothReviewTrack(), {}, {7, 25}), InputError);
}

}  // namespace
}  // namespace clm3d
