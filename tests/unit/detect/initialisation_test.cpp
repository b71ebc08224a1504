// Tests of core/detect/initialisation: stateFromPoints recovers a known pose and shape from its
// own projection (all points, missing points, noisy points; 3D and planar models), rejects too
// few points; stateFromBox puts the mean shape near the truth of a detected render.
#include "core/detect/initialisation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// A state of the fixture model at the given angles with every shape coefficient at `sd` standard
// deviations (alternating signs), 450 mm away, slightly off-centre and scaled.
FitState knownState(const ClmModel& model, double pitchDeg, double yawDeg, double rollDeg,
                    double sd = 1.5) {
  FitState state;
  state.pose = Pose::fromDegrees(pitchDeg, yawDeg, rollDeg, {12.0, -7.0, -450.0}, 1.04);
  state.shape = Eigen::VectorXd::Zero(model.shape.modeCount());
  for (int k = 0; k < state.shape.size(); ++k) {
    state.shape[k] = (k % 2 == 0 ? sd : -sd) * std::sqrt(model.shape.variances[k]);
  }
  if (model.shape.dims == 2) {
    state.pose.pitch = 0.0;
    state.pose.yaw = 0.0;
  }
  return state;
}

Camera testCamera() {
  return Camera::fromVerticalFov(640, 480, 45.0);
}

double maxError(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b,
                const std::vector<bool>& use = {}) {
  double worst = 0.0;
  for (int i = 0; i < a.cols(); ++i) {
    if (!use.empty() && !use[static_cast<std::size_t>(i)]) continue;
    worst = std::max(worst, (a.col(i) - b.col(i)).norm());
  }
  return worst;
}

// Earlobes, a cheek, a chin point, a brow end and a mouth corner missing.
std::vector<bool> someMissing() {
  std::vector<bool> present(25, true);
  for (int i : {18, 24, 23, 22, 6, 15}) present[static_cast<std::size_t>(i)] = false;
  return present;
}

class StateFromPointsYaw : public ::testing::TestWithParam<double> {};

TEST_P(StateFromPointsYaw, RecoversItsOwnProjectionExactly) {
  const ClmModel& model = test::fitTestModel();
  const Camera camera = testCamera();
  const FitState truth = knownState(model, 6.0, GetParam(), 8.0);
  const Eigen::Matrix2Xd points = projectState(model, camera, truth);

  const FitState found = stateFromPoints(model, camera, points, {});
  const Eigen::Matrix2Xd again = projectState(model, camera, found);
  EXPECT_LT(maxError(again, points), 0.05);
  EXPECT_NEAR(degrees(found.pose.yaw), GetParam(), 0.5);
  EXPECT_NEAR(degrees(found.pose.pitch), 6.0, 0.5);
  EXPECT_NEAR(degrees(found.pose.roll), 8.0, 0.5);
  // At 450 mm perspective barely tells depth from size: the image scale S / Tz is exact, the depth
  // itself leans towards scale 1 (the truth has 1.04).
  EXPECT_NEAR(found.pose.scale / found.pose.translation.z(),
              truth.pose.scale / truth.pose.translation.z(), 1e-3 * truth.pose.scale / 450.0);
  EXPECT_NEAR(found.pose.translation.z() / truth.pose.translation.z(), 1.0, 0.05);
  for (int k = 0; k < truth.shape.size(); ++k) {
    EXPECT_NEAR(found.shape[k], truth.shape[k], 0.05 * std::sqrt(model.shape.variances[k]))
        << "mode " << k;
  }
}

TEST_P(StateFromPointsYaw, RecoversWithMissingPoints) {
  const ClmModel& model = test::fitTestModel();
  const Camera camera = testCamera();
  const FitState truth = knownState(model, -5.0, GetParam(), -4.0);
  const Eigen::Matrix2Xd points = projectState(model, camera, truth);
  const std::vector<bool> present = someMissing();
  Eigen::Matrix2Xd given = points;
  for (int i = 0; i < 25; ++i) {
    if (!present[static_cast<std::size_t>(i)]) given.col(i).setConstant(std::nan(""));
  }

  const FitState found = stateFromPoints(model, camera, given, present);
  const Eigen::Matrix2Xd again = projectState(model, camera, found);
  EXPECT_LT(maxError(again, points, present), 0.05);
  // The missing points follow from the model.
  EXPECT_LT(maxError(again, points), 0.5);
  EXPECT_NEAR(degrees(found.pose.yaw), GetParam(), 1.0);
}

TEST_P(StateFromPointsYaw, NoisyPointsGiveANearbyState) {
  const ClmModel& model = test::fitTestModel();
  const Camera camera = testCamera();
  const FitState truth = knownState(model, 0.0, GetParam(), 3.0, 1.0);
  const Eigen::Matrix2Xd points = projectState(model, camera, truth);
  const std::vector<bool> present = someMissing();
  std::mt19937 random(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::Matrix2Xd given = points;
  for (int i = 0; i < 25; ++i) given.col(i) += Eigen::Vector2d(noise(random), noise(random));

  const FitState found = stateFromPoints(model, camera, given, present);
  const Eigen::Matrix2Xd again = projectState(model, camera, found);
  const double iod = (points.col(7) - points.col(10)).norm();
  EXPECT_LT(test::meanPointError(again, points) / iod, 0.03) << "iod " << iod;
  EXPECT_NEAR(degrees(found.pose.yaw), GetParam(), 6.0);
}

// From a start 12 degrees of yaw, 10 of roll and 15 pixels away, with its shape at the mean,
// stateNearPoints reaches the state whose projection the points are, keeping the start's depth.
TEST_P(StateFromPointsYaw, NearAStartRecoversTheProjectionAndKeepsTheDepth) {
  const ClmModel& model = test::fitTestModel();
  const Camera camera = testCamera();
  const FitState truth = knownState(model, 4.0, GetParam(), -6.0);
  const Eigen::Matrix2Xd points = projectState(model, camera, truth);
  FitState start = truth;
  start.pose.yaw += radians(12.0);
  start.pose.roll += radians(10.0);
  start.pose.translation.x() += 15.0 * -truth.pose.translation.z() / camera.focalX();
  start.shape.setZero();

  const FitState found = stateNearPoints(model, camera, points, {}, start);
  EXPECT_EQ(found.pose.translation.z(), start.pose.translation.z());
  EXPECT_LT(maxError(projectState(model, camera, found), points), 0.05);
  EXPECT_NEAR(degrees(found.pose.yaw), GetParam(), 0.5);
  EXPECT_NEAR(degrees(found.pose.roll), -6.0, 0.5);
  // Without the points it would stay where it started: the start is off by pixels, not hundredths.
  EXPECT_GT(maxError(projectState(model, camera, start), points), 5.0);
  EXPECT_THROW(stateNearPoints(model, camera, points, {}, FitState{}), InputError);
}

INSTANTIATE_TEST_SUITE_P(Yaws, StateFromPointsYaw, ::testing::Values(-40.0, 0.0, 40.0));

TEST(StateFromPoints, PlanarModelRecoversItsOwnProjection) {
  const ClmModel& model = test::fitTestModel2D();
  ASSERT_EQ(model.shape.dims, 2);
  const Camera camera = testCamera();
  const FitState truth = knownState(model, 0.0, 0.0, 12.0);
  const Eigen::Matrix2Xd points = projectState(model, camera, truth);

  const FitState found = stateFromPoints(model, camera, points, {});
  EXPECT_LT(maxError(projectState(model, camera, found), points), 0.05);
  EXPECT_EQ(found.pose.yaw, 0.0);
  EXPECT_EQ(found.pose.pitch, 0.0);
  EXPECT_NEAR(degrees(found.pose.roll), 12.0, 0.2);

  const std::vector<bool> present = someMissing();
  const FitState partial = stateFromPoints(model, camera, points, present);
  EXPECT_LT(maxError(projectState(model, camera, partial), points, present), 0.05);
}

TEST(StateFromPoints, RejectsTooFewOrMalformedPoints) {
  const ClmModel& model = test::fitTestModel();
  const Camera camera = testCamera();
  const Eigen::Matrix2Xd points = projectState(model, camera, knownState(model, 0, 0, 0));
  std::vector<bool> three(25, false);
  three[0] = three[7] = three[10] = true;
  try {
    stateFromPoints(model, camera, points, three);
    FAIL() << "3 points accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("at least 4"), std::string::npos) << e.what();
  }
  std::vector<bool> four = three;
  four[11] = true;
  EXPECT_NO_THROW(stateFromPoints(model, camera, points, four));
  EXPECT_THROW(stateFromPoints(model, camera, points.leftCols(24), {}), InputError);
  EXPECT_THROW(stateFromPoints(model, camera, points, std::vector<bool>(24, true)), InputError);
  Eigen::Matrix2Xd broken = points;
  broken(0, 3) = std::nan("");
  EXPECT_THROW(stateFromPoints(model, camera, broken, {}), InputError);
}

TEST(StateFromBox, ProfileBoxesTurnTheirWayAndFrontalBoxesFaceTheCamera) {
  const ClmModel& model = test::fitTestModel();
  const Camera camera = testCamera();
  FaceBox box;
  box.box = cv::Rect2d(250, 150, 140, 140);
  const FitState frontal = stateFromBox(model, camera, box);
  EXPECT_EQ(frontal.pose.yaw, 0.0);
  EXPECT_EQ(frontal.shape.size(), model.shape.modeCount());
  // The calibrated eye distance and eye midpoint.
  const BoxCalibration c = boxCalibration(DetectorKind::Cascade, false);
  const Eigen::Matrix2Xd points = projectState(model, camera, frontal);
  const Eigen::Vector2d mid = 0.5 * (points.col(7) + points.col(10));
  EXPECT_NEAR((points.col(7) - points.col(10)).norm(), c.iodPerWidth * 140.0, 0.02 * 140.0);
  EXPECT_NEAR(mid.x(), 320.0 + c.eyeOffsetX * 140.0, 0.5);
  EXPECT_NEAR(mid.y(), 220.0 + c.eyeOffsetY * 140.0, 0.5);

  box.profile = true;
  const FitState left = stateFromBox(model, camera, box);
  box.mirrored = true;
  const FitState right = stateFromBox(model, camera, box);
  EXPECT_LT(left.pose.yaw, -radians(20.0));
  EXPECT_GT(right.pose.yaw, radians(20.0));
  EXPECT_NEAR(left.pose.yaw, -right.pose.yaw, 1e-12);

  // The planar model never turns.
  EXPECT_EQ(stateFromBox(test::fitTestModel2D(), camera, box).pose.yaw, 0.0);
  box.box.width = 0.0;
  EXPECT_THROW(stateFromBox(model, camera, box), InputError);
}

}  // namespace
}  // namespace clm3d
