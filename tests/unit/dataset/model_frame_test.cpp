// The frame clm3d render puts a mesh in (viewingFrame): the same as training's modelFrame wherever
// the landmarks allow it (levelled on the eye centres, or on the eye corners when the centres are
// missing; landmark 1 at the origin), and never failing for want of landmarks: the file's axes
// and the given origin instead.
#include "core/dataset/detail/model_frame.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>

#include "core/mesh/mesh_transform.hpp"

namespace clm3d {
namespace {

// thesis25 points of a head whose file has +z up and -y out of the face, turned 10 degrees about
// the file's up axis (so levelling on the eyes changes the rotation), landmark 1 at (5, 6, 7).
LandmarkSet turnedHead() {
  LandmarkSet points(25, 3);
  const Eigen::Vector3d one(5.0, 6.0, 7.0);
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(10.0 * 3.14159265358979 / 180.0, Eigen::Vector3d::UnitZ()).matrix();
  // Model x (subject's left) is file x, model up is file +z, model front is file -y.
  const auto place = [&](int i, double x, double up, double front) {
    points.set(i, Eigen::Vector3d(one + turn * Eigen::Vector3d(x, -front, up)));
  };
  place(0, 0.0, 0.0, 0.0);       // 1: between the eyes
  place(7, 32.0, -2.0, -8.0);    // 8: left eye centre
  place(10, -32.0, -2.0, -8.0);  // 11: right eye centre
  place(1, 45.0, -2.0, -12.0);   // 2, 3: outer corners
  place(2, -45.0, -2.0, -12.0);
  place(8, 18.0, -2.0, -10.0);  // 9, 10: inner corners
  place(9, -18.0, -2.0, -10.0);
  place(11, 0.0, -45.0, 20.0);  // 12: nose tip
  return points;
}

const Eigen::Vector3d kUp(0.0, 0.0, 1.0);
const Eigen::Vector3d kFront(0.0, -1.0, 0.0);
const Eigen::Vector3d kFallback(100.0, 200.0, 300.0);

// viewingFrame levelled on the eyes, checked against training's modelFrame.
ModelFrame expectTrainingsFrame(const LandmarkSet& points) {
  std::string why;
  const auto reference = modelFrame(points, Scheme::thesis25(), kUp, kFront, true, why);
  EXPECT_TRUE(reference) << why;
  bool levelled = false;
  const ModelFrame frame =
      viewingFrame(&points, &Scheme::thesis25(), kUp, kFront, true, kFallback, levelled);
  EXPECT_TRUE(levelled);
  if (reference) {
    EXPECT_TRUE(frame.rotation.isApprox(reference->rotation, 1e-12));
    EXPECT_TRUE(frame.origin.isApprox(reference->origin, 1e-12));
  }
  return frame;
}

TEST(ViewingFrame, MatchesTrainingsFrameWhenTheLandmarksAllowIt) {
  const LandmarkSet points = turnedHead();
  const ModelFrame frame = expectTrainingsFrame(points);
  // Levelled: the right eye centre to the left one is +x.
  const Eigen::Vector3d eyes = frame.rotation * (points.point(7) - points.point(10));
  EXPECT_NEAR(eyes.normalized().x(), 1.0, 1e-9);
  EXPECT_TRUE(applyFrame(frame, points).point(0).isZero(1e-12));
}

TEST(ViewingFrame, LevelsOnTheEyeCornersWithoutTheEyeCentres) {
  LandmarkSet points = turnedHead();
  points.setMissing(7);
  points.setMissing(10);
  expectTrainingsFrame(points);
}

TEST(ViewingFrame, FallsBackToTheFileAxesAndTheGivenOrigin) {
  const Eigen::Matrix3d fileAxes = axesToModelRotation(kUp, kFront);
  bool levelled = true;
  // No landmarks at all.
  ModelFrame frame = viewingFrame(nullptr, nullptr, kUp, kFront, true, kFallback, levelled);
  EXPECT_FALSE(levelled);
  EXPECT_TRUE(frame.rotation.isApprox(fileAxes));
  EXPECT_TRUE(frame.origin.isApprox(kFallback));
  // Levelling not asked for (--orient file): the file's axes about landmark 1.
  const LandmarkSet points = turnedHead();
  frame = viewingFrame(&points, &Scheme::thesis25(), kUp, kFront, false, kFallback, levelled);
  EXPECT_FALSE(levelled);
  EXPECT_TRUE(frame.rotation.isApprox(fileAxes));
  EXPECT_TRUE(frame.origin.isApprox(points.point(0)));
  // No eyes and no landmark 1: the file's axes about the given origin (modelFrame refuses).
  LandmarkSet bare(25, 3);
  bare.set(11, points.point(11));
  frame = viewingFrame(&bare, &Scheme::thesis25(), kUp, kFront, true, kFallback, levelled);
  EXPECT_FALSE(levelled);
  EXPECT_TRUE(frame.rotation.isApprox(fileAxes));
  EXPECT_TRUE(frame.origin.isApprox(kFallback));
  std::string why;
  EXPECT_FALSE(modelFrame(bare, Scheme::thesis25(), kUp, kFront, true, why));
}

}  // namespace
}  // namespace clm3d
