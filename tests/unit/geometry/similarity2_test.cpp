// The 2D similarity: a known similarity is recovered exactly from its points, applying and
// inverting round-trip (point by point and for a whole set), and coinciding source points give
// the identity.
#include "core/geometry/similarity2.hpp"

#include <gtest/gtest.h>

namespace clm3d {
namespace {

Eigen::Matrix2Xd face() {
  Eigen::Matrix2Xd points(2, 6);
  points << -0.5, 0.5, 0.0, -0.4, 0.4, 0.0,  //
      0.0, 0.0, 0.6, 1.0, 1.0, 1.5;
  return points;
}

TEST(Similarity2, RoundTripsAndFitsExactly) {
  const Eigen::Matrix2Xd from = face();
  Similarity2 frame;
  frame.scale = 37.0;
  frame.angle = 0.3;
  frame.translation = Eigen::Vector2d(120.0, -4.0);
  Eigen::Matrix2Xd to(2, from.cols());
  for (Eigen::Index i = 0; i < from.cols(); ++i)
    to.col(i) = frame.apply(Eigen::Vector2d(from.col(i)));
  const Similarity2 fitted = alignSimilarity2(from, to);
  EXPECT_NEAR(fitted.scale, 37.0, 1e-9);
  EXPECT_NEAR(fitted.angle, 0.3, 1e-9);
  EXPECT_TRUE(fitted.translation.isApprox(frame.translation, 1e-9));
  EXPECT_TRUE(frame.inverse(Eigen::Vector2d(to.col(3))).isApprox(from.col(3), 1e-12));
  EXPECT_TRUE(frame.apply(from).isApprox(to, 1e-12));
  EXPECT_TRUE(frame.inverse(to).isApprox(from, 1e-12));
}

TEST(Similarity2, CoincidingSourcePointsGiveTheIdentity) {
  const Similarity2 identity = alignSimilarity2(Eigen::Matrix2Xd::Ones(2, 4), face().leftCols(4));
  EXPECT_EQ(identity.scale, 1.0);
  EXPECT_EQ(identity.angle, 0.0);
  EXPECT_EQ(identity.translation, Eigen::Vector2d::Zero());
}

}  // namespace
}  // namespace clm3d
