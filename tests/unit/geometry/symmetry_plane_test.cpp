#include "core/geometry/symmetry_plane.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace clm3d {
namespace {

// Five landmarks: a left/right pair (0, 1), another pair (2, 3) and a mid-line point (4) of a face
// whose symmetry plane is x = 0, then turned and moved.
struct Face {
  Eigen::Matrix3Xd points{3, 5};
  std::vector<int> mirror{1, 0, 3, 2, 4};
};

Face turnedFace(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& shift) {
  Face face;
  face.points.col(0) << 30, 5, 0;
  face.points.col(1) << -30, 5, 0;
  face.points.col(2) << 25, -60, -5;
  face.points.col(3) << -25, -60, -5;
  face.points.col(4) << 0, -40, 20;
  for (int i = 0; i < 5; ++i) face.points.col(i) = rotation * face.points.col(i) + shift;
  return face;
}

TEST(SymmetryPlane, ReflectsOnePairMemberOntoTheOther) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 1, 0.1).normalized()).toRotationMatrix();
  const Face face = turnedFace(rotation, {10, -3, 50});
  // Pair (2, 3) and the mid-line point placed; the plane must map point 0 onto point 1 too.
  const std::vector<bool> present{false, false, true, true, true};
  const auto plane = estimateSymmetryPlane(face.points, present, face.mirror);
  ASSERT_TRUE(plane.has_value());
  EXPECT_LT((plane->reflect(face.points.col(0)) - face.points.col(1)).norm(), 1e-9);
  EXPECT_NEAR(plane->normal.norm(), 1.0, 1e-12);
  EXPECT_GT(plane->normal.dot(Eigen::Vector3d::UnitX()), 0.0);
}

TEST(SymmetryPlane, MidlinePointsAloneGiveThePlaneWhenTheySpanIt) {
  Eigen::Matrix3Xd points(3, 4);
  points << 0, 0, 0, 5,  // the last point is the only off-plane one (a pair member)
      10, -40, -80, 0,   //
      5, 25, 0, 0;
  const std::vector<int> mirror{0, 1, 2, 3};
  const std::vector<bool> present{true, true, true, false};
  const auto plane = estimateSymmetryPlane(points, present, mirror);
  ASSERT_TRUE(plane.has_value());
  EXPECT_NEAR(std::abs(plane->normal.x()), 1.0, 1e-9);
  EXPECT_NEAR(plane->offset, 0.0, 1e-9);
  EXPECT_LT((plane->reflect({7, 1, 2}) - Eigen::Vector3d(-7, 1, 2)).norm(), 1e-9);
}

TEST(SymmetryPlane, OneMidlinePointUsesTheFallbackNormalThroughIt) {
  const Face face = turnedFace(Eigen::Matrix3d::Identity(), {4, 0, 0});
  const std::vector<bool> present{true, false, false, false, true};
  const auto plane = estimateSymmetryPlane(face.points, present, face.mirror);
  ASSERT_TRUE(plane.has_value());
  EXPECT_NEAR(plane->signedDistance(face.points.col(4)), 0.0, 1e-12);
  EXPECT_LT((plane->normal - Eigen::Vector3d::UnitX()).norm(), 1e-12);
}

TEST(SymmetryPlane, NothingLocatesThePlaneWithoutAPairOrMidlinePoint) {
  const Face face = turnedFace(Eigen::Matrix3d::Identity(), {0, 0, 0});
  EXPECT_FALSE(estimateSymmetryPlane(face.points, {true, false, true, false, false}, face.mirror));
  EXPECT_THROW(estimateSymmetryPlane(face.points, {true}, face.mirror), std::invalid_argument);
}

}  // namespace
}  // namespace clm3d
