// LandmarkSet keeps points and their presence, 2D sets keep z = 0, and misuse is reported.
#include "core/scheme/landmark_set.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace clm3d {
namespace {

TEST(LandmarkSet, StartsAllMissing) {
  const LandmarkSet set(4, 3);
  EXPECT_EQ(set.size(), 4);
  EXPECT_EQ(set.dims(), 3);
  EXPECT_EQ(set.presentCount(), 0);
  for (int i = 0; i < 4; ++i) EXPECT_FALSE(set.has(i));
  EXPECT_THROW(set.point(0), std::logic_error);
}

TEST(LandmarkSet, SetAndMissing) {
  LandmarkSet set(3, 2);
  set.set(0, Eigen::Vector2d(1.5, 2.5));
  set.set(2, Eigen::Vector3d(3.0, 4.0, 99.0));  // z dropped in 2D
  EXPECT_EQ(set.presentCount(), 2);
  EXPECT_EQ(set.point(0), Eigen::Vector3d(1.5, 2.5, 0.0));
  EXPECT_EQ(set.point(2), Eigen::Vector3d(3.0, 4.0, 0.0));
  EXPECT_EQ(set.presentMask(), (std::vector<bool>{true, false, true}));
  const auto m = set.matrix();
  EXPECT_EQ(m.cols(), 3);
  EXPECT_TRUE(std::isnan(m(0, 1)) && std::isnan(m(1, 1)) && std::isnan(m(2, 1)));
  EXPECT_EQ(m(0, 2), 3.0);
  set.setMissing(0);
  EXPECT_FALSE(set.has(0));
  EXPECT_EQ(set.presentCount(), 1);
}

TEST(LandmarkSet, ThreeDimensionalKeepsZ) {
  LandmarkSet set(1, 3);
  set.set(0, Eigen::Vector3d(1.0, 2.0, -3.0));
  EXPECT_EQ(set.point(0).z(), -3.0);
}

TEST(LandmarkSet, RejectsMisuse) {
  EXPECT_THROW(LandmarkSet(3, 4), std::invalid_argument);
  EXPECT_THROW(LandmarkSet(-1, 2), std::invalid_argument);
  LandmarkSet set(2, 2);
  EXPECT_THROW(set.set(2, Eigen::Vector2d(0, 0)), std::out_of_range);
  EXPECT_THROW(set.has(-1), std::out_of_range);
  EXPECT_THROW(set.set(0, Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(), 0)),
               std::invalid_argument);
  EXPECT_THROW(set.set(0, Eigen::Vector2d(std::numeric_limits<double>::infinity(), 0)),
               std::invalid_argument);
}

TEST(LandmarkSet, Equality) {
  LandmarkSet a(2, 2);
  LandmarkSet b(2, 2);
  EXPECT_EQ(a, b);
  a.set(1, Eigen::Vector2d(1, 1));
  EXPECT_FALSE(a == b);
  b.set(1, Eigen::Vector2d(1, 1));
  EXPECT_EQ(a, b);
  EXPECT_FALSE(LandmarkSet(2, 2) == LandmarkSet(2, 3));
}

TEST(LandmarkSet, CentroidIsTheMeanOfThePresentPoints) {
  LandmarkSet set(4, 3);
  EXPECT_EQ(set.centroid(), Eigen::Vector3d::Zero());  // none present
  set.set(0, Eigen::Vector3d(1.0, 2.0, 3.0));
  set.set(2, Eigen::Vector3d(3.0, -2.0, 5.0));
  set.set(3, Eigen::Vector3d(100.0, 100.0, 100.0));
  set.setMissing(3);
  EXPECT_TRUE(set.centroid().isApprox(Eigen::Vector3d(2.0, 0.0, 4.0)));
}

}  // namespace
}  // namespace clm3d
