// Several sequences pooled per tracker and errors bucketed by a truth column: pooling equals the
// frames' union (the same summary as one table holding both), motion never spans two sequences,
// bucket edges from a width cover every value, and a bucket's summary is the summary of its frames.
#include "core/eval/error_buckets.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.hpp"
#include "tests/unit/eval/eval_test_tables.hpp"

namespace clm3d {
namespace {

TEST(EvalPooled, PoolingTwoSequencesSummarisesTheirFramesTogether) {
  const auto truth = test::truthTable(6);
  const auto near = test::offsetTable(truth, 6.0, 0.0);  // 0.1 everywhere
  const auto far = test::offsetTable(truth, 18.0, 0.0);  // 0.3 everywhere: not converged
  const auto pooled =
      evaluateSequences({{&truth, &near, "a-truth", "a-pred"}, {&truth, &far, "b-truth", "b-pred"}},
                        Scheme::thesis25());
  ASSERT_EQ(pooled.frames.size(), 12u);
  EXPECT_EQ(pooled.frames[5].sequence, 0);
  EXPECT_EQ(pooled.frames[6].sequence, 1);
  EXPECT_EQ(pooled.source, "a-pred, b-pred");
  EXPECT_EQ(pooled.summary.normalisedFrames, 12);
  EXPECT_NEAR(pooled.summary.mean, 0.2, 1e-12);
  EXPECT_NEAR(pooled.summary.convergenceRate, 0.5, 1e-12);
  // Constant offsets: no jitter within a sequence; the jump from 0.1 to 0.3 between the two
  // sequences is not a frame pair (5 pairs each).
  EXPECT_EQ(pooled.summary.jitterFrames, 10);
  EXPECT_NEAR(pooled.summary.jitter, 0.0, 1e-12);
}

TEST(EvalPooled, APredictionOfAnotherSequenceIsRefused) {
  const auto truth = test::truthTable(4);
  const auto longer = test::offsetTable(test::truthTable(6), 1.0, 0.0);
  // Alone, extra rows are ignored and counted.
  EXPECT_EQ(evaluateSequence(truth, longer, Scheme::thesis25()).summary.extraPredictionRows, 2);
  try {
    evaluateSequences(
        {{&truth, &truth, "a.csv", "a-pred.csv"}, {&truth, &longer, "b.csv", "b-pred.csv"}},
        Scheme::thesis25());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("b-pred.csv: 2 of its 6 rows are for frames its ground "
                                         "truth b.csv (4 frames) does not have"),
              std::string::npos)
        << e.what();
  }
}

TEST(EvalBuckets, FramesFallIntoTheirBucketsByTheTruthColumn) {
  auto truth = test::truthTable(8);
  for (auto& row : truth.rows) row.pose = Pose::fromDegrees(0.0, -20.0 + 6.0 * row.frame, 0.0);
  // Frames 0..3 (yaw -20..-2) are 6 px off (0.1), frames 4..7 (yaw 4..22) 12 px (0.2).
  const auto prediction = test::shiftedTable(
      truth, [](int frame, int) { return Eigen::Vector2d(frame < 4 ? 6.0 : 12.0, 0.0); });
  EvalOptions options;
  options.keyColumn = "yaw";
  const auto evaluation =
      evaluateSequences({{&truth, &prediction, "t", "p"}}, Scheme::thesis25(), options);
  EXPECT_NEAR(evaluation.frames[0].key, -20.0, 1e-9);

  BucketSpec spec;
  spec.column = "yaw";
  spec.width = 10.0;
  EXPECT_EQ(bucketEdges(spec, {evaluation}), (std::vector<double>{-20, -10, 0, 10, 20, 30}));
  spec.width = 0.0;
  spec.edges = {-25.0, 0.0, 25.0};
  const auto buckets = bucketErrors({evaluation}, spec, Scheme::thesis25());
  ASSERT_EQ(buckets.buckets.at(0).size(), 2u);
  EXPECT_EQ(buckets.buckets[0][0].summary.normalisedFrames, 4);
  EXPECT_NEAR(buckets.buckets[0][0].summary.mean, 0.1, 1e-12);
  EXPECT_NEAR(buckets.buckets[0][1].summary.mean, 0.2, 1e-12);
  EXPECT_EQ(buckets.outside.at(0), 0);

  // Edges that leave frames out count them as outside; bad specs are refused.
  spec.edges = {0.0, 10.0};
  EXPECT_EQ(bucketErrors({evaluation}, spec, Scheme::thesis25()).outside.at(0), 6);
  spec.edges = {10.0, 0.0};
  EXPECT_THROW(bucketEdges(spec, {evaluation}), InputError);
  spec.width = 5.0;
  EXPECT_THROW(bucketEdges(spec, {evaluation}), InputError);  // both

  // An unknown column names the truth.
  options.keyColumn = "yawn";
  try {
    evaluateSequences({{&truth, &prediction, "t.csv", "p"}}, Scheme::thesis25(), options);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.csv: has no column \"yawn\""), std::string::npos)
        << e.what();
  }
}

TEST(TrackColumns, ValuesByName) {
  TrackTable table;
  table.extraColumns = {"keyframe"};
  TrackRow row;
  row.frame = 3;
  row.pose = Pose::fromDegrees(10.0, -30.0, 5.0);
  row.extraCells = {"1"};
  EXPECT_EQ(trackColumnValue(table, row, "frame"), 3.0);
  EXPECT_NEAR(*trackColumnValue(table, row, "yaw"), -30.0, 1e-9);
  EXPECT_NEAR(*trackColumnValue(table, row, "pitch"), 10.0, 1e-9);
  EXPECT_EQ(trackColumnValue(table, row, "keyframe"), 1.0);
  EXPECT_FALSE(trackColumnValue(table, row, "x_1").has_value());
  row.pose.reset();
  EXPECT_TRUE(std::isnan(*trackColumnValue(table, row, "roll")));
}

}  // namespace
}  // namespace clm3d
