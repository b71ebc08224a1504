#include "core/geometry/procrustes.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

Eigen::Matrix3Xd samplePoints(int count) {
  Eigen::Matrix3Xd points(3, count);
  for (int i = 0; i < count; ++i) {
    points.col(i) << 30.0 * std::sin(0.7 * i), 20.0 * std::cos(1.3 * i),
        10.0 * std::sin(2.1 * i + 0.4);
  }
  return points;
}

TEST(Procrustes, RecoversKnownSimilarity) {
  Similarity3 truth;
  truth.scale = 1.7;
  truth.rotation =
      Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 2, -0.5).normalized()).toRotationMatrix();
  truth.translation = {12, -4, 300};
  const Eigen::Matrix3Xd source = samplePoints(25);
  const Eigen::Matrix3Xd target = truth.apply(source);

  const Similarity3 fit = alignSimilarity(source, target);
  EXPECT_NEAR(fit.scale, truth.scale, 1e-9);
  EXPECT_TRUE(fit.rotation.isApprox(truth.rotation, 1e-9));
  EXPECT_TRUE(fit.translation.isApprox(truth.translation, 1e-9));
  EXPECT_LT(rmsDistance(fit.apply(source), target), 1e-9);
}

TEST(Procrustes, RigidKeepsUnitScale) {
  Similarity3 truth;
  truth.scale = 2.0;
  truth.rotation = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3Xd source = samplePoints(10);
  const Similarity3 fit = alignSimilarity(source, truth.apply(source), {}, false);
  EXPECT_DOUBLE_EQ(fit.scale, 1.0);
  EXPECT_TRUE(fit.rotation.isApprox(truth.rotation, 1e-9));
}

TEST(Procrustes, SelectionIgnoresMissingOrOutlyingPoints) {
  Similarity3 truth;
  truth.scale = 0.8;
  truth.rotation =
      Eigen::AngleAxisd(-1.1, Eigen::Vector3d(0.2, 1, 0.1).normalized()).toRotationMatrix();
  truth.translation = {-5, 9, 2};
  const Eigen::Matrix3Xd source = samplePoints(12);
  Eigen::Matrix3Xd target = truth.apply(source);
  std::vector<bool> use(12, true);
  target.col(3).setConstant(std::numeric_limits<double>::quiet_NaN());
  target.col(7) += Eigen::Vector3d(500, 0, 0);
  use[3] = false;
  use[7] = false;
  const Similarity3 fit = alignSimilarity(source, target, use);
  EXPECT_NEAR(fit.scale, truth.scale, 1e-9);
  EXPECT_TRUE(fit.rotation.isApprox(truth.rotation, 1e-9));
  EXPECT_LT(rmsDistance(fit.apply(source), target, use), 1e-9);
}

TEST(Procrustes, NeverReturnsAReflection) {
  const Eigen::Matrix3Xd source = samplePoints(15);
  Eigen::Matrix3Xd mirrored = source;
  mirrored.row(0) *= -1.0;
  const Similarity3 fit = alignSimilarity(source, mirrored);
  EXPECT_NEAR(fit.rotation.determinant(), 1.0, 1e-9);
}

TEST(Procrustes, InverseUndoes) {
  Similarity3 s;
  s.scale = 3.0;
  s.rotation = Eigen::AngleAxisd(0.9, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  s.translation = {1, 2, 3};
  const Eigen::Vector3d p(4, -5, 6);
  EXPECT_TRUE(s.inverse().apply(s.apply(p)).isApprox(p, 1e-12));
}

TEST(Procrustes, RejectsDegenerateInput) {
  Eigen::Matrix3Xd line(3, 4);
  line << 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3;
  EXPECT_THROW(alignSimilarity(line, line), Error);
  EXPECT_THROW(alignSimilarity(samplePoints(2), samplePoints(2)), Error);
  EXPECT_THROW(alignSimilarity(samplePoints(5), samplePoints(6)), Error);
}

}  // namespace
}  // namespace clm3d
