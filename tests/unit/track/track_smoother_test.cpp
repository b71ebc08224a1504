// Tests of the one-euro point smoother: it removes most of the noise of a still point, follows a
// moving one with less lag the higher beta, passes the first frame, NaN points and restarts through
// unchanged, and rejects settings that cannot be honoured.
#include "core/track/track_smoother.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

constexpr double kFps = 30.0;
constexpr double kEyeDistance = 60.0;  // pixels

SmoothingSettings on(double minCutoff, double beta) {
  SmoothingSettings settings;
  settings.enabled = true;
  settings.minCutoffHz = minCutoff;
  settings.beta = beta;
  return settings;
}

// Standard deviation of the filtered x of a still point with Gaussian noise of 1 pixel.
double stillNoise(const SmoothingSettings& settings) {
  PointSmoother smoother(settings);
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  double sum = 0.0, squares = 0.0;
  int count = 0;
  for (int f = 0; f < 300; ++f) {
    Eigen::Matrix2Xd points(2, 1);
    points << 100.0 + noise(random), 50.0;
    smoother.filter(points, f / kFps, kEyeDistance);
    if (f < 30) continue;  // settled
    sum += points(0, 0);
    squares += points(0, 0) * points(0, 0);
    ++count;
  }
  const double mean = sum / count;
  return std::sqrt(squares / count - mean * mean);
}

// How far the filtered point trails a point moving at `speed` pixels per frame, after a second.
double rampLag(const SmoothingSettings& settings, double speed) {
  PointSmoother smoother(settings);
  Eigen::Matrix2Xd points(2, 1);
  for (int f = 0; f <= 30; ++f) {
    points << 100.0 + speed * f, 50.0;
    smoother.filter(points, f / kFps, kEyeDistance);
  }
  return 100.0 + speed * 30 - points(0, 0);
}

TEST(PointSmoother, AStillPointShimmersLess) {
  const double smoothed = stillNoise(on(1.0, 1.0));
  EXPECT_LT(smoothed, 0.4);  // unfiltered: 1 pixel; a 1 Hz low-pass at 30 fps keeps about 0.3
  EXPECT_LT(stillNoise(on(0.5, 1.0)), smoothed);
}

TEST(PointSmoother, HigherBetaFollowsMotionWithLessLag) {
  const double still = rampLag(on(1.0, 0.0), 3.0);
  const double fast = rampLag(on(1.0, 5.0), 3.0);
  EXPECT_GT(still, 5.0);  // a fixed 1 Hz low-pass trails a 90 px/s point by about 14 px
  EXPECT_LT(fast, 0.5 * still);
  EXPECT_GT(fast, 0.0);
}

TEST(PointSmoother, FirstFrameNanPointsAndRestartsPassThrough) {
  PointSmoother smoother(on(1.0, 0.0));
  EXPECT_FALSE(smoother.hasHistory());
  Eigen::Matrix2Xd points(2, 2);
  points << 10.0, 20.0, 30.0, 40.0;
  const Eigen::Matrix2Xd first = points;
  smoother.filter(points, 0.0, kEyeDistance);
  EXPECT_EQ(points, first);
  EXPECT_TRUE(smoother.hasHistory());

  Eigen::Matrix2Xd moved(2, 2);
  moved << 20.0, std::nan(""), 30.0, std::nan("");
  smoother.filter(moved, 1.0 / kFps, kEyeDistance);
  EXPECT_GT(moved(0, 0), 10.0);  // filtered towards 20
  EXPECT_LT(moved(0, 0), 20.0);
  EXPECT_TRUE(std::isnan(moved(0, 1)));

  // The NaN point comes back: it starts afresh where it is.
  Eigen::Matrix2Xd back(2, 2);
  back << 20.0, 90.0, 30.0, 90.0;
  smoother.filter(back, 2.0 / kFps, kEyeDistance);
  EXPECT_EQ(back(0, 1), 90.0);

  smoother.restart();
  EXPECT_FALSE(smoother.hasHistory());
  Eigen::Matrix2Xd jump(2, 2);
  jump << 200.0, 200.0, 200.0, 200.0;
  const Eigen::Matrix2Xd raw = jump;
  smoother.filter(jump, 3.0 / kFps, kEyeDistance);
  EXPECT_EQ(jump, raw);

  // A timestamp that does not move on is a restart too, not a division by zero.
  Eigen::Matrix2Xd same = raw;
  same.array() += 5.0;
  const Eigen::Matrix2Xd sameRaw = same;
  smoother.filter(same, 3.0 / kFps, kEyeDistance);
  EXPECT_EQ(same, sameRaw);
}

TEST(PointSmoother, RejectsSettingsItCannotHonour) {
  EXPECT_THROW(PointSmoother(on(0.0, 1.0)), InputError);
  EXPECT_THROW(PointSmoother(on(1.0, -1.0)), InputError);
  SmoothingSettings derivative = on(1.0, 1.0);
  derivative.derivativeCutoffHz = std::nan("");
  EXPECT_THROW(PointSmoother{derivative}, InputError);
}

}  // namespace
}  // namespace clm3d
