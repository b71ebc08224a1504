#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "core/common/error.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"
#include "core/geometry/projection.hpp"

namespace clm3d {
namespace {

constexpr double kTol = 1e-9;

// The thesis's matrices (eq. A.5-A.9) as printed are for row vectors; these are their transposes,
// written out element by element, to check Pose against the text rather than against Eigen.
Eigen::Matrix4d thesisRotX(double t) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(1, 1) = std::cos(t);
  m(1, 2) = -std::sin(t);
  m(2, 1) = std::sin(t);
  m(2, 2) = std::cos(t);
  return m;
}
Eigen::Matrix4d thesisRotY(double p) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 0) = std::cos(p);
  m(0, 2) = std::sin(p);
  m(2, 0) = -std::sin(p);
  m(2, 2) = std::cos(p);
  return m;
}
Eigen::Matrix4d thesisRotZ(double g) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 0) = std::cos(g);
  m(0, 1) = -std::sin(g);
  m(1, 0) = std::sin(g);
  m(1, 1) = std::cos(g);
  return m;
}

TEST(Pose, SignConventions) {
  const Eigen::Vector3d nose(0, 0, 1);
  const Pose zeroT = Pose::fromDegrees(0, 90, 0, Eigen::Vector3d::Zero());
  EXPECT_TRUE(zeroT.toEye(nose).isApprox(Eigen::Vector3d(1, 0, 0), kTol)) << "yaw turns nose to +x";
  const Pose pitch = Pose::fromDegrees(90, 0, 0, Eigen::Vector3d::Zero());
  EXPECT_TRUE(pitch.toEye(nose).isApprox(Eigen::Vector3d(0, -1, 0), kTol)) << "pitch nose down";
  const Pose roll = Pose::fromDegrees(0, 0, 90, Eigen::Vector3d::Zero());
  EXPECT_TRUE(roll.toEye(Eigen::Vector3d(1, 0, 0)).isApprox(Eigen::Vector3d(0, 1, 0), kTol));
}

TEST(Pose, ViewMatrixIsThesisComposition) {
  const Pose pose = Pose::fromDegrees(12, -37, 8, {4, -7, -600}, 1.3);
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topRightCorner<3, 1>() = pose.translation;
  Eigen::Matrix4d s = Eigen::Matrix4d::Identity();
  s.topLeftCorner<3, 3>() *= pose.scale;
  const Eigen::Matrix4d expected =
      t * s * thesisRotX(pose.pitch) * thesisRotY(pose.yaw) * thesisRotZ(pose.roll);
  EXPECT_TRUE(pose.viewMatrix().isApprox(expected, kTol));

  const Eigen::Vector3d p(31, -12, 45);
  const Eigen::Vector4d viaMatrix = pose.viewMatrix() * p.homogeneous();
  EXPECT_TRUE(pose.toEye(p).isApprox(viaMatrix.head<3>(), kTol));
  EXPECT_NEAR(pose.rotation().determinant(), 1.0, kTol);
}

TEST(Pose, MatrixFormMatchesPointForm) {
  const Pose pose = Pose::fromDegrees(-20, 50, -5, {10, 20, -800}, 0.9);
  Eigen::Matrix3Xd points(3, 4);
  points << 0, 10, -30, 5, 0, 20, 4, -40, 0, 15, 60, 2;
  const Eigen::Matrix3Xd eye = pose.toEye(points);
  for (int i = 0; i < 4; ++i)
    EXPECT_TRUE(eye.col(i).isApprox(pose.toEye(Eigen::Vector3d(points.col(i))), kTol));
}

TEST(Angles, DegreesRadiansRoundTrip) {
  EXPECT_NEAR(radians(180.0), std::numbers::pi, kTol);
  EXPECT_NEAR(degrees(radians(37.5)), 37.5, kTol);
}

TEST(Camera, ProjectionMatrixMatchesEquationA10) {
  const Camera camera = Camera::fromVerticalFov(640, 480, 30.0, 10.0, 5000.0);
  const Eigen::Matrix4d m = camera.projectionMatrix();
  EXPECT_NEAR(m(0, 0), 2 * camera.near / (2 * camera.right), kTol);
  EXPECT_NEAR(m(1, 1), 2 * camera.near / (2 * camera.top), kTol);
  EXPECT_NEAR(m(2, 2), -(5000.0 + 10.0) / (5000.0 - 10.0), kTol);
  EXPECT_NEAR(m(2, 3), -2 * 5000.0 * 10.0 / (5000.0 - 10.0), kTol);
  EXPECT_NEAR(m(3, 2), -1.0, kTol);
  EXPECT_NEAR(camera.right / camera.top, 640.0 / 480.0, kTol);
  EXPECT_NEAR(camera.focalX(), camera.focalY(), 1e-6);
  EXPECT_NEAR(camera.focalY(), 240.0 / std::tan(radians(15.0)), 1e-6);
}

TEST(Camera, PixelsAgreeWithClipSpace) {
  const Camera camera = Camera::fromVerticalFov(320, 240, 25.0);
  const Eigen::Vector3d eye(37.0, -21.0, -700.0);
  const Eigen::Vector4d clip = camera.projectionMatrix() * eye.homogeneous();
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
  const Eigen::Vector2d pixel = camera.eyeToPixel(eye);
  EXPECT_NEAR(pixel.x(), (ndc.x() + 1) / 2 * 320 - 0.5, 1e-9);
  EXPECT_NEAR(pixel.y(), (1 - ndc.y()) / 2 * 240 - 0.5, 1e-9);
}

TEST(Camera, KnownPixels) {
  const Camera camera = Camera::fromVerticalFov(256, 256, 20.0);
  EXPECT_TRUE(camera.eyeToPixel({0, 0, -500}).isApprox(Eigen::Vector2d(127.5, 127.5), kTol));
  // A point on the right clipping plane lands on the right edge of the image, one on the top
  // plane on the top edge (y down).
  const double d = 900.0;
  EXPECT_NEAR(camera.eyeToPixel({camera.right * d / camera.near, 0, -d}).x(), 255.5, 1e-9);
  EXPECT_NEAR(camera.eyeToPixel({0, camera.top * d / camera.near, -d}).y(), -0.5, 1e-9);
}

TEST(Camera, PixelEyeRoundTrip) {
  const Camera camera = Camera::fromVerticalFov(640, 480, 40.0);
  const Eigen::Vector2d pixel(101.25, 377.5);
  const Eigen::Vector3d eye = camera.pixelToEye(pixel, 812.0);
  EXPECT_NEAR(eye.z(), -812.0, kTol);
  EXPECT_TRUE(camera.eyeToPixel(eye).isApprox(pixel, 1e-9));
}

TEST(Camera, RejectsBadParameters) {
  EXPECT_THROW(Camera::fromVerticalFov(0, 10, 30), Error);
  EXPECT_THROW(Camera::fromVerticalFov(10, 10, 0), Error);
  EXPECT_THROW(Camera::fromVerticalFov(10, 10, 30, 10, 5), Error);
}

TEST(Projection, PointsAndBatchAgree) {
  const Camera camera = Camera::fromVerticalFov(640, 480, 30.0);
  const Pose pose = Pose::fromDegrees(10, -25, 3, {5, -8, -650});
  Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Random(3, 7) * 80.0;
  const Eigen::Matrix2Xd batch = projectPoints(points, pose, camera);
  for (int i = 0; i < 7; ++i) {
    EXPECT_TRUE(batch.col(i).isApprox(projectPoint(points.col(i), pose, camera), 1e-12));
  }
}

TEST(Projection, DistanceToFitSpansRequestedShare) {
  const Camera camera = Camera::fromVerticalFov(300, 200, 30.0);
  const double radius = 120.0;
  const double tz = distanceToFit(radius, camera, 0.8);
  ASSERT_LT(tz, 0.0);
  const Pose pose = Pose::fromDegrees(0, 0, 0, {0, 0, tz});
  const double top = projectPoint({0, radius, 0}, pose, camera).y();
  const double bottom = projectPoint({0, -radius, 0}, pose, camera).y();
  EXPECT_NEAR(bottom - top, 0.8 * 200.0, 1e-6);
}

}  // namespace
}  // namespace clm3d
