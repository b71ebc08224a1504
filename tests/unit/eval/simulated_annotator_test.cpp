// The simulated annotator of the correction benchmark on a 30-frame track whose counts are known
// by hand: a lost stretch (frames 4-11, every point 0.4 eye distances off), a frame the general
// model always gets slightly wrong (frame 20: 15 points 0.09 off, error 0.054, no point far enough
// from its neighbours for the review list) and a failed frame (25, every point 0.12 off). A fake
// tracker re-tracks by the studio's rules (judgeRetrackedRow) and fixes frame 20 once adapted. In
// frame order, by the review list (with one fallback), and adapting (which spares frame 20).
#include "core/eval/simulated_annotator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

constexpr int kAnnotatorFrames = 30;
constexpr double kAnnotatorEyes = 50.0;  // pixels between thesis25's eye centres (7, 10)

Eigen::Matrix2Xd annotatorTruthPoints(int frame) {
  Eigen::Matrix2Xd points(2, 25);
  for (int k = 0; k < 25; ++k) {
    points.col(k) = Eigen::Vector2d(100.0 + 12.0 * (k % 5) + frame, 100.0 + 12.0 * (k / 5));
  }
  points.col(7) = Eigen::Vector2d(75.0 + frame, 90.0);
  points.col(10) = Eigen::Vector2d(75.0 + kAnnotatorEyes + frame, 90.0);
  return points;
}

TrackRow annotatorRow(int frame, const Eigen::Matrix2Xd& points, bool success = true) {
  TrackRow row;
  row.frame = frame;
  row.timestamp = frame / 30.0;
  row.success = success;
  row.confidence = success ? 0.9 : 0.1;
  row.points = points;
  return row;
}

// The first `count` points moved `share` eye distances along x.
Eigen::Matrix2Xd annotatorMoved(Eigen::Matrix2Xd points, double share, int count = 25) {
  for (int k = 0; k < count; ++k) points(0, k) += share * kAnnotatorEyes;
  return points;
}

TrackTable annotatorTruth() {
  TrackTable table;
  table.landmarkCount = 25;
  for (int f = 0; f < kAnnotatorFrames; ++f) {
    table.rows.push_back(annotatorRow(f, annotatorTruthPoints(f)));
  }
  // Frame 28 has no truth: it is never scored, whatever the track says.
  table.rows[28].points.setConstant(std::numeric_limits<double>::quiet_NaN());
  return table;
}

// What the general model tracks a frame as: right, but frame 20 always 15 points 0.09 off.
Eigen::Matrix2Xd generalModelPoints(int frame) {
  return frame == 20 ? annotatorMoved(annotatorTruthPoints(frame), 0.09, 15)
                     : annotatorTruthPoints(frame);
}

TrackTable annotatorFirstTrack() {
  TrackTable table;
  table.landmarkCount = 25;
  for (int f = 0; f < kAnnotatorFrames; ++f) {
    Eigen::Matrix2Xd points = generalModelPoints(f);
    if (f >= 4 && f <= 11) points = annotatorMoved(points, 0.4);
    if (f == 28) points = annotatorMoved(points, 1.0);
    table.rows.push_back(f == 25 ? annotatorRow(f, annotatorMoved(points, 0.12), false)
                                 : annotatorRow(f, points));
  }
  return table;
}

// Re-tracks as retrackSpan does (judgeRetrackedRow on each fresh row against the frame's previous
// one), each frame coming out as the general model, or once adapted the truth, has it.
class FakeAnnotatorTracker final : public AnnotatorTracker {
 public:
  SpanRetrack retrack(int corrected, const Eigen::Matrix2Xd& points, const std::vector<int>& frames,
                      const std::vector<TrackRow>& previous, const RetrackRules& rules) override {
    EXPECT_TRUE(points.isApprox(annotatorTruthPoints(corrected))) << "frame " << corrected;
    ++retracks;
    SpanRetrack out;
    for (const int f : frames) {
      const TrackRow fresh =
          annotatorRow(f, adapted ? annotatorTruthPoints(f) : generalModelPoints(f));
      const RetrackStop verdict =
          judgeRetrackedRow(fresh, &previous[static_cast<std::size_t>(f)], {7, 10}, rules);
      if (verdict != RetrackStop::Failed) out.rows.push_back(fresh);
      if (verdict != RetrackStop::Continue) {
        out.stop = verdict;
        out.stoppedAt = f;
        break;
      }
    }
    return out;
  }

  std::vector<TrackRow> adapt(const GroundTruthSet& truth) override {
    adaptedOn.push_back(truth.keyframeCount());
    adapted = true;
    std::vector<TrackRow> rows;
    for (int f = 0; f < truth.frameCount(); ++f) {
      rows.push_back(annotatorRow(f, annotatorTruthPoints(f)));
    }
    return rows;
  }

  bool adapted = false;
  int retracks = 0;
  std::vector<int> adaptedOn;
};

AnnotatorRun runAnnotator(AnnotatorStrategy strategy, FakeAnnotatorTracker& tracker,
                          AnnotatorSettings settings = {}) {
  return simulateAnnotator(strategy, annotatorTruth(), annotatorFirstTrack(), Scheme::thesis25(),
                           tracker, settings);
}

TEST(SimulatedAnnotator, InOrderCorrectsTheFirstWrongFrameAndTheLoopRepairsTheLostStretch) {
  FakeAnnotatorTracker tracker;
  const AnnotatorRun run = runAnnotator(AnnotatorStrategy::InOrder, tracker);
  EXPECT_EQ(run.scoredFrames, 29);
  EXPECT_EQ(run.wrongAtStart, 10);  // 4-11, 20, 25
  // Frame 4 re-tracks 5-12 (rejoining the old track at 12), 20 and 25 rejoin at once.
  EXPECT_EQ(run.correctedFrames, (std::vector<int>{4, 20, 25}));
  EXPECT_EQ(run.corrected, 3);
  EXPECT_EQ(run.drags, 25 + 15 + 25);
  EXPECT_EQ(run.fallbacks, 0);
  EXPECT_EQ(run.adaptations, 0);
  EXPECT_EQ(run.retracks, 3);
  EXPECT_EQ(run.retrackedFrames, 8 + 1 + 1);
  EXPECT_EQ(run.wrongAtEnd, 0);
  EXPECT_FALSE(run.capped);
  EXPECT_EQ(run.result.keyframeCount(), 3);
  EXPECT_TRUE(run.result.keyframe[20]);
}

TEST(SimulatedAnnotator, ReviewTakesTheListsOrderAndFallsBackToFrameOrderForWhatItMisses) {
  FakeAnnotatorTracker tracker;
  const AnnotatorRun run = runAnnotator(AnnotatorStrategy::Review, tracker);
  // The failed frame first, then the jump into the lost stretch; frame 20 is on no list.
  EXPECT_EQ(run.correctedFrames, (std::vector<int>{25, 4, 20}));
  EXPECT_EQ(run.drags, 25 + 25 + 15);
  EXPECT_EQ(run.fallbacks, 1);
  EXPECT_EQ(run.adaptations, 0);
  EXPECT_EQ(run.wrongAtEnd, 0);
  EXPECT_TRUE(tracker.adaptedOn.empty());
}

TEST(SimulatedAnnotator, ReviewAdaptAdaptsEveryNCorrectionsAndTheAdaptedModelSparesAFrame) {
  FakeAnnotatorTracker tracker;
  AnnotatorSettings settings;
  settings.adaptEvery = 2;
  const AnnotatorRun run = runAnnotator(AnnotatorStrategy::ReviewAdapt, tracker, settings);
  EXPECT_EQ(run.correctedFrames, (std::vector<int>{25, 4}));
  EXPECT_EQ(run.drags, 50);
  EXPECT_EQ(run.fallbacks, 0);
  EXPECT_EQ(run.adaptations, 1);
  EXPECT_EQ(tracker.adaptedOn, (std::vector<int>{2}));
  EXPECT_EQ(run.wrongAtEnd, 0);
  EXPECT_FALSE(run.result.keyframe[20]);  // the adapted model's row, not a correction
}

TEST(SimulatedAnnotator, TheCapEndsTheRunAndSaysSo) {
  FakeAnnotatorTracker tracker;
  AnnotatorSettings settings;
  settings.maxCorrections = 1;
  const AnnotatorRun run = runAnnotator(AnnotatorStrategy::InOrder, tracker, settings);
  EXPECT_EQ(run.corrected, 1);
  EXPECT_TRUE(run.capped);
  EXPECT_EQ(run.wrongAtEnd, 2);  // 20 and 25
  settings.maxCorrections = 0;
  EXPECT_TRUE(runAnnotator(AnnotatorStrategy::Review, tracker, settings).capped);
}

TEST(SimulatedAnnotator, StrategyNamesAndBadSettings) {
  for (const AnnotatorStrategy strategy :
       {AnnotatorStrategy::InOrder, AnnotatorStrategy::Review, AnnotatorStrategy::ReviewAdapt}) {
    EXPECT_EQ(annotatorStrategyByName(annotatorStrategyName(strategy)), strategy);
  }
  EXPECT_THROW(annotatorStrategyByName("random"), InputError);
  FakeAnnotatorTracker tracker;
  AnnotatorSettings settings;
  settings.adaptEvery = 0;
  EXPECT_THROW(runAnnotator(AnnotatorStrategy::ReviewAdapt, tracker, settings), InputError);
  TrackTable shortTruth = annotatorTruth();
  shortTruth.rows.erase(shortTruth.rows.begin());  // row 0 is frame 1
  EXPECT_THROW(simulateAnnotator(AnnotatorStrategy::InOrder, shortTruth, annotatorFirstTrack(),
                                 Scheme::thesis25(), tracker),
               InputError);
}

}  // namespace
}  // namespace clm3d
