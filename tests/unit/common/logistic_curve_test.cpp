// The logistic curve fitted to labelled scores: it rises through the scores where the labels
// change, stays finite on separable scores, and with balanced classes does not follow the ratio
// of the sample.
#include "core/common/logistic_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace clm3d {
namespace {

TEST(LogisticCurve, RisesWhereTheLabelsChangeAndStaysFiniteOnSeparableScores) {
  std::vector<double> scores;
  std::vector<bool> labels;
  for (int k = 0; k < 20; ++k) {
    scores.push_back(0.2 + 0.01 * k);  // 0.20..0.39: wrong
    labels.push_back(false);
    scores.push_back(0.6 + 0.01 * k);  // 0.60..0.79: right
    labels.push_back(true);
  }
  const LogisticCurve curve = fitLogisticCurve(scores, labels);
  EXPECT_TRUE(std::isfinite(curve.slope) && std::isfinite(curve.offset));
  EXPECT_GT(curve.slope, 0.0);
  EXPECT_LT(curve(0.3), 0.05);
  EXPECT_GT(curve(0.7), 0.95);
  EXPECT_NEAR(curve(0.495), 0.5, 0.1);
}

TEST(LogisticCurve, BalancedClassesDoNotFollowTheSampleRatio) {
  // Overlapping classes, nine wrong scores to each right one.
  std::vector<double> scores;
  std::vector<bool> labels;
  for (int k = 0; k < 90; ++k) {
    scores.push_back(0.3 + 0.4 * (k % 10) / 9.0);  // 0.3..0.7
    labels.push_back(false);
  }
  for (int k = 0; k < 10; ++k) {
    scores.push_back(0.5 + 0.4 * k / 9.0);  // 0.5..0.9
    labels.push_back(true);
  }
  const LogisticCurve plain = fitLogisticCurve(scores, labels);
  LogisticFitSettings balanced;
  balanced.balanced = true;
  const LogisticCurve even = fitLogisticCurve(scores, labels, balanced);
  // Between the class means (0.5 and 0.7): about even when balanced, the 9:1 prior when not.
  EXPECT_NEAR(even(0.6), 0.5, 0.15);
  EXPECT_LT(plain(0.6), 0.25);
  EXPECT_GT(even(0.8), plain(0.8));
}

// Scores far from 0 (the log-odds of near-certain probabilities, as `clm3d calibrate` fits them):
// Newton's full step from slope 1 overshot to slopes of 1e5 here; halved until the likelihood
// rises, it lands on the curve the labels say.
TEST(LogisticCurve, ScoresFarFromZeroStillGiveTheLabelsShare) {
  std::vector<double> scores;
  std::vector<bool> labels;
  for (int k = 0; k < 60; ++k) {
    scores.push_back(20.0 + 0.01 * k);
    labels.push_back(k % 2 == 0);  // half right
  }
  for (int k = 0; k < 40; ++k) {
    scores.push_back(-5.0 - 0.01 * k);
    labels.push_back(false);
  }
  const LogisticCurve curve = fitLogisticCurve(scores, labels);
  ASSERT_TRUE(std::isfinite(curve.slope) && std::isfinite(curve.offset));
  EXPECT_NEAR(curve(20.3), 0.5, 0.05);
  EXPECT_LT(curve(-5.2), 0.05);
}

TEST(LogisticCurve, OneClassOnlyGivesTheStart) {
  const LogisticCurve curve = fitLogisticCurve({0.1, 0.2, 0.3}, {true, true, true});
  EXPECT_EQ(curve.slope, 1.0);
  EXPECT_EQ(curve.offset, 0.0);
}

}  // namespace
}  // namespace clm3d
