// The pose jitter of training renders: each view's renders cover the view's share of the pose
// range (half the way to the neighbouring centres) unless coverage is switched off.
#include "core/train/training_sample.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace clm3d {
namespace {

struct Spread {
  double pitch = 0.0, yaw = 0.0, roll = 0.0;  // largest |offset| from the centre
};

Spread spreadOf(const TrainSettings& settings, const ViewCentre& view) {
  Spread s;
  for (int sample = 0; sample < 400; ++sample) {
    const SampleSpec spec = drawSample(settings, view, 7, 0, 0, sample);
    s.pitch = std::max(s.pitch, std::abs(spec.pitchDeg - view.pitchDeg));
    s.yaw = std::max(s.yaw, std::abs(spec.yawDeg - view.yawDeg));
    s.roll = std::max(s.roll, std::abs(spec.rollDeg));
  }
  return s;
}

TEST(TrainingSample, PitchAndYawCoverHalfTheWayToTheNeighbouringViews) {
  TrainSettings settings;  // yaws -60..60 and pitches -30..30, 30 degrees apart
  for (const ViewCentre view : {ViewCentre{0, 0}, ViewCentre{-30, -60}}) {
    const Spread s = spreadOf(settings, view);
    EXPECT_GT(s.yaw, 13.5);
    EXPECT_LE(s.yaw, 15.0);
    EXPECT_GT(s.pitch, 13.5);
    EXPECT_LE(s.pitch, 15.0);
    EXPECT_LE(s.roll, settings.perturbation.rotationDeg);  // roll is not a view axis
  }
  settings.yawsDeg = {-40, 0, 20};
  EXPECT_LE(spreadOf(settings, {0, 0}).yaw, 10.0);  // the nearer neighbour sets the range
  EXPECT_GT(spreadOf(settings, {0, 0}).yaw, 9.0);
}

TEST(TrainingSample, CoverageOffOrASingleViewKeepsTheRotationJitter) {
  TrainSettings settings;
  settings.perturbation.viewCoverage = 0.0;
  Spread s = spreadOf(settings, {0, 30});
  EXPECT_LE(s.yaw, 5.0);
  EXPECT_GT(s.yaw, 4.5);
  EXPECT_LE(s.pitch, 5.0);
  settings.perturbation.viewCoverage = 1.0;
  settings.singleView = true;
  s = spreadOf(settings, {0, 0});
  EXPECT_LE(s.yaw, 5.0);
  EXPECT_LE(s.pitch, 5.0);
}

}  // namespace
}  // namespace clm3d
