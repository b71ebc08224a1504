// The error of thesis eq. 5.1 on hand-computed examples: known offsets give known errors, regions
// are averaged separately, missing and failed frames count against convergence, and the CDF is
// monotone and reaches 1 when every frame is predicted.
#include "core/eval/landmark_error.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.hpp"
#include "core/common/number_text.hpp"
#include "tests/unit/eval/eval_test_tables.hpp"

namespace clm3d {
namespace {

const RegionError& region(const ErrorSummary& summary, const std::string& name) {
  for (const auto& r : summary.regions) {
    if (r.name == name) return r;
  }
  throw std::logic_error("no region " + name);
}

TEST(EvalLandmarkError, ThesisSchemeNormalisesByTheEyeCentres) {
  // Thesis points 8 and 11 (1-based): the centres of the eyes.
  EXPECT_EQ(Scheme::thesis25().normalisationPair(), std::make_pair(7, 10));
}

TEST(EvalLandmarkError, KnownOffsetGivesKnownError) {
  const auto truth = test::truthTable(5);
  // (6, 8) pixels is 10 pixels: 10 / 60 of the inter-ocular distance at every point.
  const auto evaluation =
      evaluateSequence(truth, test::offsetTable(truth, 6.0, 8.0), Scheme::thesis25());
  const auto& s = evaluation.summary;
  ASSERT_EQ(evaluation.frames.size(), 5u);
  for (const auto& frame : evaluation.frames) {
    EXPECT_DOUBLE_EQ(frame.interOcular, 60.0);
    EXPECT_NEAR(frame.error, 1.0 / 6.0, 1e-12);
    EXPECT_TRUE(frame.converged);
    for (const double e : frame.pointErrors) EXPECT_NEAR(e, 1.0 / 6.0, 1e-12);
  }
  EXPECT_EQ(s.truthFrames, 5);
  EXPECT_EQ(s.scoredFrames, 5);
  EXPECT_EQ(s.convergedFrames, 5);
  EXPECT_NEAR(s.mean, 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(s.median, 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(s.sd, 0.0, 1e-12);
  EXPECT_NEAR(s.min, 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(s.max, 1.0 / 6.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.convergenceRate, 1.0);
  EXPECT_EQ(s.truePoints, 125);
  EXPECT_EQ(s.foundPoints, 125);
  EXPECT_DOUBLE_EQ(s.withinThreshold, 1.0);
  ASSERT_EQ(s.regions.size(), 5u);
  for (const auto& r : s.regions) EXPECT_NEAR(r.mean, 1.0 / 6.0, 1e-12) << r.name;
  EXPECT_NEAR(s.meanPointError, 1.0 / 6.0, 1e-12);
}

TEST(EvalLandmarkError, ErrorAboveTheThresholdIsNeitherConvergedNorFound) {
  const auto truth = test::truthTable(3);
  // 12 pixels: 0.2 > 0.18.
  const auto s =
      evaluateSequence(truth, test::offsetTable(truth, 0.0, -12.0), Scheme::thesis25()).summary;
  EXPECT_NEAR(s.mean, 0.2, 1e-12);
  EXPECT_EQ(s.convergedFrames, 0);
  EXPECT_DOUBLE_EQ(s.convergenceRate, 0.0);
  EXPECT_EQ(s.foundPoints, 0);
  EXPECT_DOUBLE_EQ(s.withinThreshold, 0.0);
  // A looser threshold changes both.
  EvalOptions loose;
  loose.threshold = 0.25;
  const auto l =
      evaluateSequence(truth, test::offsetTable(truth, 0.0, -12.0), Scheme::thesis25(), loose)
          .summary;
  EXPECT_DOUBLE_EQ(l.convergenceRate, 1.0);
  EXPECT_DOUBLE_EQ(l.withinThreshold, 1.0);
}

TEST(EvalLandmarkError, RegionsAreAveragedSeparately) {
  const auto& scheme = Scheme::thesis25();
  const auto truth = test::truthTable(2);
  const int jaw = 4, mouth = 3;
  ASSERT_EQ(scheme.regions()[jaw].name, "jaw");
  ASSERT_EQ(scheme.regions()[mouth].name, "mouth");
  // Jaw points 30 pixels off (0.5), mouth points 6 pixels off (0.1), the rest exact.
  const auto prediction = test::shiftedTable(truth, [&](int, int i) {
    if (scheme.regionOf(i) == jaw) return Eigen::Vector2d(30.0, 0.0);
    if (scheme.regionOf(i) == mouth) return Eigen::Vector2d(0.0, 6.0);
    return Eigen::Vector2d(0.0, 0.0);
  });
  const auto s = evaluateSequence(truth, prediction, scheme).summary;
  EXPECT_NEAR(region(s, "jaw").mean, 0.5, 1e-12);
  EXPECT_EQ(region(s, "jaw").points, 14);
  EXPECT_DOUBLE_EQ(region(s, "jaw").withinThreshold, 0.0);
  EXPECT_NEAR(region(s, "mouth").mean, 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(region(s, "mouth").withinThreshold, 1.0);
  EXPECT_NEAR(region(s, "left_eye").mean, 0.0, 1e-12);
  EXPECT_NEAR(region(s, "nose").mean, 0.0, 1e-12);
  // 7 jaw points at 0.5 and 4 mouth points at 0.1 over 25 points.
  EXPECT_NEAR(s.mean, (7 * 0.5 + 4 * 0.1) / 25, 1e-12);
  EXPECT_NEAR(s.meanPointError, (7 * 0.5 + 4 * 0.1) / 25, 1e-12);
  EXPECT_EQ(s.foundPoints, 2 * 18);
  EXPECT_NEAR(s.withinThreshold, 18.0 / 25.0, 1e-12);
}

TEST(EvalLandmarkError, NormalisesByTheTrueNotThePredictedEyeDistance) {
  const auto truth = test::truthTable(1);
  // The prediction twice as large about the left eye centre: its eye distance is 120 pixels.
  auto prediction = truth;
  const Eigen::Vector2d centre = truth.rows[0].points.col(7);
  for (int i = 0; i < 25; ++i) {
    prediction.rows[0].points.col(i) = centre + 2.0 * (truth.rows[0].points.col(i) - centre);
  }
  const auto frame = evaluateSequence(truth, prediction, Scheme::thesis25()).frames[0];
  EXPECT_DOUBLE_EQ(frame.interOcular, 60.0);
  EXPECT_NEAR(frame.pointErrors[10], 1.0, 1e-12);  // 60 pixels off
  EXPECT_NEAR(frame.pointErrors[7], 0.0, 1e-12);
  const double expected = (truth.rows[0].points.col(3) - centre).norm() / 60.0;
  EXPECT_NEAR(frame.pointErrors[3], expected, 1e-12);
}

// A frame the tracker reported as tracked while its points were off is a wrong success; a frame
// reported as failed is not, whatever its error.
TEST(EvalLandmarkError, SucceededFramesAboveTheWrongLimitAreCounted) {
  const auto truth = test::truthTable(10);
  TrackTable prediction = truth;
  const auto shift = [](TrackRow& row, double share) {
    const double eyes = (row.points.col(7) - row.points.col(10)).norm();
    row.points.row(0).array() += share * eyes;  // every point off by `share` of the eye distance
  };
  for (auto& row : prediction.rows) {
    if (row.frame == 2) shift(row, 0.5);  // reported tracked, 0.5 off
    if (row.frame == 3) {
      shift(row, 0.5);  // 0.5 off, reported lost
      row.success = false;
    }
    if (row.frame == 4) shift(row, 0.2);  // tracked, 0.2 off
  }
  EXPECT_EQ(evaluateSequence(truth, prediction, Scheme::thesis25()).summary.wrongSuccesses, 1);
  EvalOptions options;
  options.wrongAbove = 0.1;
  EXPECT_EQ(evaluateSequence(truth, prediction, Scheme::thesis25(), options).summary.wrongSuccesses,
            2);
}

TEST(EvalLandmarkError, MissingAndFailedFramesCountAgainstConvergence) {
  const auto truth = test::truthTable(10);
  TrackTable prediction = truth;
  prediction.rows.erase(prediction.rows.begin() + 3, prediction.rows.begin() + 5);  // 3, 4
  for (auto& row : prediction.rows) {
    if (row.frame == 5) row.success = false;           // exact points, but flagged lost
    if (row.frame == 6) row.points.setConstant(kNan);  // no points at all
  }
  TrackRow extra = prediction.rows.back();  // a frame the truth does not have
  extra.frame = 42;
  prediction.rows.push_back(extra);

  const auto evaluation = evaluateSequence(truth, prediction, Scheme::thesis25());
  const auto& s = evaluation.summary;
  EXPECT_EQ(s.normalisedFrames, 10);
  EXPECT_EQ(s.predictedFrames, 8);
  EXPECT_EQ(s.succeededFrames, 7);
  EXPECT_EQ(s.scoredFrames, 7);  // the failed frame 5 is scored, frame 6 has no points
  EXPECT_EQ(s.convergedFrames, 6);
  EXPECT_DOUBLE_EQ(s.convergenceRate, 0.6);
  EXPECT_EQ(s.extraPredictionRows, 1);
  EXPECT_EQ(s.truePoints, 250);
  EXPECT_EQ(s.foundPoints, 175);
  EXPECT_DOUBLE_EQ(s.withinThreshold, 0.7);
  EXPECT_FALSE(evaluation.frames[3].predicted);
  EXPECT_TRUE(std::isnan(evaluation.frames[3].error));
  EXPECT_TRUE(evaluation.frames[5].predicted);
  EXPECT_FALSE(evaluation.frames[5].converged);
  EXPECT_DOUBLE_EQ(evaluation.frames[5].error, 0.0);
  EXPECT_TRUE(std::isnan(evaluation.frames[6].error));
  // The CDF counts the frames without a prediction as above every threshold.
  EXPECT_DOUBLE_EQ(s.cdf.back().frames, 0.7);
  EXPECT_DOUBLE_EQ(s.cdf.back().points, 0.7);
  EXPECT_EQ(scoredFrameErrors(evaluation).size(), 7u);
}

TEST(EvalLandmarkError, MissingPointsAndUnnormalisedTruthFramesAreSkipped) {
  auto truth = test::truthTable(4);
  truth.rows[1].points.col(10).setConstant(kNan);        // no right eye centre: frame 1 unusable
  truth.rows[2].points.col(20).setConstant(kNan);        // one point not annotated
  auto prediction = test::offsetTable(truth, 3.0, 4.0);  // 5 pixels: 1/12
  prediction.rows[3].points.col(0).setConstant(kNan);    // one point not predicted
  const auto evaluation = evaluateSequence(truth, prediction, Scheme::thesis25());
  const auto& s = evaluation.summary;
  EXPECT_FALSE(evaluation.frames[1].normalised);
  EXPECT_EQ(s.truthFrames, 4);
  EXPECT_EQ(s.normalisedFrames, 3);
  EXPECT_EQ(s.scoredFrames, 3);
  EXPECT_TRUE(std::isnan(evaluation.frames[2].pointErrors[20]));
  EXPECT_NEAR(evaluation.frames[2].error, 1.0 / 12.0, 1e-12);
  EXPECT_EQ(s.truePoints, 25 + 24 + 25);
  EXPECT_EQ(s.foundPoints, 25 + 24 + 24);  // the unpredicted point is not found
  EXPECT_DOUBLE_EQ(s.convergenceRate, 1.0);
}

TEST(EvalLandmarkError, CdfIsMonotoneAndEndsAtOne) {
  const auto truth = test::truthTable(40);
  // Errors growing with the frame: frame f is off by f / 2 pixels (up to 19.5 / 60 = 0.325).
  const auto prediction =
      test::shiftedTable(truth, [](int f, int) { return Eigen::Vector2d(f / 2.0, 0.0); });
  const auto s = evaluateSequence(truth, prediction, Scheme::thesis25()).summary;
  ASSERT_EQ(s.cdf.size(), 51u);
  EXPECT_DOUBLE_EQ(s.cdf.front().threshold, 0.0);
  EXPECT_NEAR(s.cdf.back().threshold, 0.5, 1e-12);
  for (std::size_t k = 1; k < s.cdf.size(); ++k) {
    EXPECT_GE(s.cdf[k].frames, s.cdf[k - 1].frames);
    EXPECT_GE(s.cdf[k].points, s.cdf[k - 1].points);
  }
  EXPECT_DOUBLE_EQ(s.cdf.back().frames, 1.0);
  EXPECT_DOUBLE_EQ(s.cdf.back().points, 1.0);
  EXPECT_DOUBLE_EQ(s.cdf.front().frames, 1.0 / 40.0);  // frame 0 is exact
  // error <= 0.11 for f / 120 <= 0.11: frames 0..13.
  EXPECT_DOUBLE_EQ(s.cdf[11].frames, 14.0 / 40.0);
  // Frames with error < 0.18 (f < 21.6): 22 of 40 converge.
  EXPECT_DOUBLE_EQ(s.convergenceRate, 22.0 / 40.0);
  EXPECT_NEAR(s.median, 19.5 / 120.0, 1e-12);  // between frames 19 and 20
}

TEST(EvalLandmarkError, TruthRowsOutOfOrderAreSorted) {
  auto truth = test::truthTable(3);
  std::swap(truth.rows[0], truth.rows[2]);
  const auto evaluation = evaluateSequence(truth, truth, Scheme::thesis25());
  EXPECT_EQ(evaluation.frames[0].frame, 0);
  EXPECT_EQ(evaluation.frames[2].frame, 2);
  EXPECT_DOUBLE_EQ(evaluation.summary.mean, 0.0);
}

std::string evaluationError(const TrackTable& truth, const TrackTable& prediction) {
  try {
    evaluateSequence(truth, prediction, Scheme::thesis25(), {}, "gt.csv", "pred.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(EvalLandmarkError, MismatchedOrUnusableTablesAreInputErrors) {
  const auto truth = test::truthTable(2);
  TrackTable small;
  small.landmarkCount = 3;
  TrackRow row;
  row.points = Eigen::Matrix2Xd::Zero(2, 3);
  small.rows.push_back(row);
  EXPECT_EQ(evaluationError(truth, small),
            "pred.csv: has 3 landmarks but the ground truth gt.csv has 25");
  EXPECT_EQ(evaluationError(small, small).rfind("gt.csv: has 3 landmarks", 0), 0u);
  EXPECT_EQ(evaluationError(TrackTable{25, {}}, truth), "gt.csv: has no frames");
  auto blind = truth;
  for (auto& r : blind.rows) r.points.col(7).setConstant(kNan);
  EXPECT_EQ(evaluationError(blind, truth).rfind("gt.csv: no frame has both normalisation", 0), 0u)
      << evaluationError(blind, truth);
}

}  // namespace
}  // namespace clm3d

namespace clm3d {
namespace {

// Jitter: motion of the prediction the truth's motion does not explain, per eye distance.
TEST(EvalJitter, MotionTheTruthExplainsIsNoJitter) {
  const auto truth = test::truthTable(6);  // moving 3 pixels a frame
  const auto offset =
      evaluateSequence(truth, test::offsetTable(truth, 0.0, 2.0), Scheme::thesis25());
  EXPECT_EQ(offset.summary.jitterFrames, 5);
  EXPECT_NEAR(offset.summary.jitter, 0.0, 1e-12);
  EXPECT_TRUE(std::isnan(offset.frames[0].jitter));   // no previous frame
  EXPECT_NEAR(offset.summary.lagFrames, 0.0, 1e-12);  // off the motion's line: no lag
}

TEST(EvalJitter, AlternatingOffsetsAreJitter) {
  const auto truth = test::truthTable(8);
  const auto shaking = test::shiftedTable(
      truth, [](int frame, int) { return Eigen::Vector2d(0.0, frame % 2 == 0 ? 1.5 : -1.5); });
  const auto evaluation = evaluateSequence(truth, shaking, Scheme::thesis25());
  EXPECT_EQ(evaluation.summary.jitterFrames, 7);
  EXPECT_NEAR(evaluation.summary.jitter, 3.0 / test::kInterOcular, 1e-12);
  EXPECT_NEAR(evaluation.frames[3].jitter, 3.0 / test::kInterOcular, 1e-12);
}

// NMJ: the same change of the error per face size, sqrt(width x height) of the truth's point box.
// The test faces span x 90..186 and y 100..180 (eye centres at y 100, the rest at 150..180) in
// every frame: a box of 96 x 80 pixels. Each point shakes up and down by its own amplitude
// 1 + 0.1 k pixels, so its error changes by 2 (1 + 0.1 k) between frames: 4.4 on average over
// k = 0..24.
TEST(EvalNmj, AShakingTrackHasTheAnalyticNmj) {
  const auto truth = test::truthTable(9);  // moving 3 pixels a frame: not jitter
  const auto shaking = test::shiftedTable(truth, [](int frame, int point) {
    const double amplitude = 1.0 + 0.1 * point;
    return Eigen::Vector2d(0.0, frame % 2 == 0 ? amplitude : -amplitude);
  });
  const auto evaluation = evaluateSequence(truth, shaking, Scheme::thesis25());
  const double faceSize = std::sqrt(96.0 * 80.0);
  EXPECT_NEAR(evaluation.frames[4].faceSize, faceSize, 1e-12);
  EXPECT_NEAR(evaluation.summary.nmj, 4.4 / faceSize, 1e-12);
  EXPECT_NEAR(evaluation.frames[5].nmj, 4.4 / faceSize, 1e-12);
  EXPECT_TRUE(std::isnan(evaluation.frames[0].nmj));  // no previous frame
  // The eye distance's jitter is the same change over 60 pixels instead.
  EXPECT_NEAR(evaluation.summary.jitter, 4.4 / test::kInterOcular, 1e-12);
}

TEST(EvalNmj, AnOffsetTrackAndFailedFramesHaveNone) {
  auto truth = test::truthTable(6);
  auto prediction = test::offsetTable(truth, 2.0, -1.0);  // a constant error does not jitter
  prediction.rows[3].success = false;                     // frames 3 and 4 have no pair
  const auto evaluation = evaluateSequence(truth, prediction, Scheme::thesis25());
  EXPECT_NEAR(evaluation.summary.nmj, 0.0, 1e-12);
  EXPECT_TRUE(std::isnan(evaluation.frames[3].nmj));
  EXPECT_TRUE(std::isnan(evaluation.frames[4].nmj));
  EXPECT_FALSE(std::isnan(evaluation.frames[5].nmj));
}

TEST(EvalJitter, APredictionAFrameLateHasALagOfOne) {
  const auto truth = test::truthTable(6);
  const auto late = test::shiftedTable(truth, [](int, int) { return Eigen::Vector2d(-3.0, 0.0); });
  const auto evaluation = evaluateSequence(truth, late, Scheme::thesis25());
  EXPECT_NEAR(evaluation.summary.lagFrames, 1.0, 1e-12);
  EXPECT_NEAR(evaluation.summary.jitter, 0.0, 1e-12);
}

TEST(EvalJitter, FailedFramesAndTruthGapsHaveNoJitter) {
  auto truth = test::truthTable(8);
  auto prediction = test::offsetTable(truth, 1.0, 0.0);
  prediction.rows[2].success = false;        // frames 2 and 3 lose their jitter
  truth.rows.erase(truth.rows.begin() + 6);  // frame 7 has no previous truth frame
  const auto evaluation = evaluateSequence(truth, prediction, Scheme::thesis25());
  ASSERT_EQ(evaluation.frames.size(), 7U);
  EXPECT_EQ(evaluation.summary.jitterFrames, 3);  // frames 1, 4, 5
  EXPECT_TRUE(std::isnan(evaluation.frames[2].jitter));
  EXPECT_TRUE(std::isnan(evaluation.frames[3].jitter));
  EXPECT_TRUE(std::isnan(evaluation.frames[6].jitter));
  EXPECT_FALSE(std::isnan(evaluation.frames[4].jitter));
}

TEST(EvalJitter, AStillTruthHasNoLag) {
  auto truth = test::truthTable(1);
  truth.rows.push_back(truth.rows[0]);
  truth.rows[1].frame = 1;
  const auto evaluation =
      evaluateSequence(truth, test::offsetTable(truth, 1.0, 0.0), Scheme::thesis25());
  EXPECT_TRUE(std::isnan(evaluation.summary.lagFrames));
  EXPECT_NEAR(evaluation.summary.jitter, 0.0, 1e-12);
}

}  // namespace
}  // namespace clm3d
