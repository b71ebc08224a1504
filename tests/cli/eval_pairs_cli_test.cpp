// clm3d eval over several sequences at once (repeated --truth, each tracker's --pred files in the
// truths' order) and with the errors bucketed by a ground-truth column: exact figures from
// predictions whose error is known by construction, and bad input (a missing file, a prediction of
// the wrong sequence, file counts that do not pair, an unknown column) naming what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/track/track_table.hpp"
#include "tests/support/test_support.hpp"
#include "tests/unit/eval/eval_test_tables.hpp"

namespace clm3d {
namespace {

using test::runClm3d;

// A thesis25 sequence (eval_test_tables: eye centres 60 pixels apart) turning 1 degree per frame,
// yaw = sign * (frame + 0.5) (off the bucket edges). offset(frame) shifts every point of a
// prediction by that many pixels, so the frame's error is offset / 60 exactly; the truth has 0.
template <typename Offset>
TrackTable turn(int frames, double sign, Offset offset) {
  TrackTable table = test::shiftedTable(test::truthTable(frames), [&](int frame, int) {
    return Eigen::Vector2d(offset(frame), 0.0);
  });
  for (auto& row : table.rows) row.pose = Pose::fromDegrees(0.0, sign * (row.frame + 0.5), 0.0);
  return table;
}

// Two sequences of 30 frames (yaw 0.5..29.5 and -0.5..-29.5); tracker "steady" is 3 px off below 15
// degrees of |yaw| (error 0.05) and 12 px above (0.2, not converged); tracker "loose" is 6 px off
// everywhere (0.1).
struct Sequences {
  test::TempDir dir;
  std::string truthA, truthB, steadyA, steadyB, looseA, looseB;
  Sequences() {
    truthA = (dir / "a-truth.csv").string();
    truthB = (dir / "b-truth.csv").string();
    steadyA = (dir / "steady-a.csv").string();
    steadyB = (dir / "steady-b.csv").string();
    looseA = (dir / "loose-a.csv").string();
    looseB = (dir / "loose-b.csv").string();
    const auto none = [](int) { return 0.0; };
    const auto steady = [](int f) { return f < 15 ? 3.0 : 12.0; };
    const auto loose = [](int) { return 6.0; };
    writeTrackTable(truthA, turn(30, 1.0, none));
    writeTrackTable(truthB, turn(30, -1.0, none));
    writeTrackTable(steadyA, turn(30, 1.0, steady));
    writeTrackTable(steadyB, turn(30, -1.0, steady));
    writeTrackTable(looseA, turn(30, 1.0, loose));
    writeTrackTable(looseB, turn(30, -1.0, loose));
  }
  std::string twoTrackers() const {
    return "eval --truth " + truthA + " --truth " + truthB + " --pred " + steadyA + " --pred " +
           steadyB + " --label steady --pred " + looseA + " --pred " + looseB + " --label loose";
  }
};

void expectIn(const std::string& output, const std::vector<std::string>& expected) {
  for (const auto& text : expected) {
    EXPECT_NE(output.find(text), std::string::npos) << "missing \"" << text << "\" in:\n" << output;
  }
}

TEST(EvalPairsCli, PoolsSequencesPerTrackerAndBucketsByAbsoluteYaw) {
  Sequences s;
  const auto csv = s.dir / "buckets.csv";
  const auto result =
      runClm3d(s.twoTrackers() + " --bucket-by yaw --bucket-abs --bucket-width 15 --bucket-csv " +
               csv.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  expectIn(result.output,
           {"ground truth: " + s.truthA + ", " + s.truthB + " (60 frames in 2 sequences, pooled",
            "\nsteady (" + s.steadyA + ", " + s.steadyB + ")",
            "frames: 60/60 predicted, 60 succeeded (0 with an error above 0.30), 60 scored, 30 "
            "converged",
            "error: mean 0.1250, median 0.1250", "\nloose (" + s.looseA + ", " + s.looseB + ")",
            "error: mean 0.1000, median 0.1000", "Welch's t-test on frame errors, steady vs loose",
            "errors by |yaw| of the ground truth", "| prediction | figure | 0 to 15 | 15 to 30 |",
            "| steady | mean error | 0.0500 | 0.2000 | 0 |",
            "| steady | converged | 100.0% (30) | 0.0% (30) | 0 |",
            "| loose | mean error | 0.1000 | 0.1000 | 0 |", "| steady | 15 to 30 | 30 | 0.2000 |",
            "buckets: " + csv.string()});
  const std::string table = test::readFile(csv);
  expectIn(table, {"label,low,high,frames,scored,converged,error_mean,error_median,convergence,",
                   "\nsteady,0,15,30,30,30,0.050000,0.050000,1.000000,1.000000,0.050000,",
                   "\nsteady,15,30,30,30,0,0.200000,0.200000,0.000000,0.000000,",
                   "\nloose,0,15,30,30,30,0.100000,0.100000,1.000000,1.000000,"});
}

TEST(EvalPairsCli, SignedEdgesAndJson) {
  Sequences s;
  const auto result = runClm3d(
      "eval --truth " + s.truthA + " " + s.truthB + " --pred " + s.steadyA + " " + s.steadyB +
      " --bucket-by yaw --bucket-edges -30,-15,0,15,30 --wrong-above 0.15 --json");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output);
  EXPECT_EQ(json["truths"].size(), 2u);
  const auto& prediction = json["predictions"][0];
  EXPECT_EQ(prediction["files"].size(), 2u);
  EXPECT_EQ(prediction["per_frame"].size(), 60u);
  EXPECT_EQ(prediction["per_frame"][59]["sequence"], 1);
  // Every frame is reported tracked; the 30 at 0.2 are wrong successes above 0.15.
  EXPECT_DOUBLE_EQ(json["wrong_above"].get<double>(), 0.15);
  EXPECT_EQ(prediction["frames"]["succeeded_wrong"], 30);
  const auto& buckets = json["buckets"];
  EXPECT_EQ(buckets["column"], "yaw");
  EXPECT_FALSE(buckets["absolute"].get<bool>());
  const auto& b = buckets["predictions"][0]["buckets"];
  ASSERT_EQ(b.size(), 4u);
  // -30..-15: frames 15..29 of b (12 px off); -15..0: frames 0..14 of b (3 px); 0..15: frames
  // 0..14 of a; 15..30: frames 15..29 of a.
  const double means[] = {0.2, 0.05, 0.05, 0.2};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(b[k]["frames"], 15) << k;
    EXPECT_NEAR(b[k]["mean"].get<double>(), means[k], 1e-9) << k;
    EXPECT_NEAR(b[k]["convergence_rate"].get<double>(), means[k] < 0.18 ? 1.0 : 0.0, 1e-12) << k;
  }
  EXPECT_EQ(buckets["predictions"][0]["outside"], 0);
}

TEST(EvalPairsCli, BadInputNamesTheFile) {
  Sequences s;
  // A missing prediction file.
  const auto absent = (s.dir / "absent.csv").string();
  auto result = runClm3d("eval --truth " + s.truthA + " --truth " + s.truthB + " --pred " +
                         s.steadyA + " --pred " + absent);
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find(absent), std::string::npos) << result.output;

  // A prediction of a longer sequence paired with a shorter truth: frames its truth lacks.
  const auto longer = (s.dir / "longer.csv").string();
  writeTrackTable(longer, turn(40, -1.0, [](int) { return 3.0; }));
  result = runClm3d("eval --truth " + s.truthA + " --truth " + s.truthB + " --pred " + s.steadyA +
                    " --pred " + longer);
  EXPECT_EQ(result.exitCode, 1) << result.output;
  expectIn(result.output, {longer + ": 10 of its 40 rows are for frames its ground truth " +
                           s.truthB + " (30 frames) does not have"});

  // An unknown bucket column names the truth and lists the columns it has.
  result = runClm3d("eval --truth " + s.truthA + " --pred " + s.steadyA + " --bucket-by yawn " +
                    "--bucket-width 10");
  EXPECT_EQ(result.exitCode, 1) << result.output;
  expectIn(result.output, {s.truthA + ": has no column \"yawn\"", "pitch, yaw, roll"});
}

TEST(EvalPairsCli, FileCountsThatDoNotPairAreUsageErrors) {
  Sequences s;
  // Three predictions for two truths.
  auto result = runClm3d("eval --truth " + s.truthA + " --truth " + s.truthB + " --pred " +
                         s.steadyA + " --pred " + s.steadyB + " --pred " + s.looseA);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  expectIn(result.output, {"3 prediction files for 2 ground-truth files"});
  // A label per file instead of per tracker.
  result = runClm3d("eval --truth " + s.truthA + " --truth " + s.truthB + " --pred " + s.steadyA +
                    " --pred " + s.steadyB + " --label a --label b");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  expectIn(result.output, {"2 labels for 1 prediction"});
  // Bucket options without a column, and a width with edges.
  result = runClm3d("eval --truth " + s.truthA + " --pred " + s.steadyA + " --bucket-width 10");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  result = runClm3d("eval --truth " + s.truthA + " --pred " + s.steadyA +
                    " --bucket-by yaw --bucket-width 10 --bucket-edges 0,10");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  // Edges that do not increase are bad input.
  result = runClm3d("eval --truth " + s.truthA + " --pred " + s.steadyA +
                    " --bucket-by yaw --bucket-edges 10,0");
  EXPECT_EQ(result.exitCode, 1) << result.output;
  expectIn(result.output, {"edges must be finite and increasing"});
}

}  // namespace
}  // namespace clm3d
