// guessShape: a posed, deformed model shape is recovered from a few placed points; fewer than 3
// points give the frontal guess in the bounds.
#include "core/model/detail/shape_guess.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.hpp"
#include "core/geometry/procrustes.hpp"

namespace clm3d {
namespace {

constexpr int kPoints = 25;

// An irregular 25-point cloud the size of a face (mm), and one deformation mode moving the
// lower points down (a mouth opening), unit length as a model's modes are.
ShapeModel smallModel() {
  ShapeModel model;
  model.meanShape.resize(3, kPoints);
  for (int i = 0; i < kPoints; ++i) {
    model.meanShape.col(i) << 50.0 * std::sin(0.9 * i), 40.0 * std::cos(1.7 * i) - 30.0,
        15.0 * std::sin(2.3 * i + 0.5);
  }
  model.modes = Eigen::MatrixXd::Zero(3 * kPoints, 1);
  for (int i = 0; i < kPoints; ++i) {
    if (model.meanShape(1, i) < -30.0) model.modes(3 * i + 1, 0) = -1.0;
  }
  model.modes.normalize();
  model.variances = Eigen::VectorXd::Constant(1, 100.0);
  return model;
}

Similarity3 somePose() {
  Similarity3 pose;
  pose.scale = 1.1;
  pose.rotation =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.1, 1, 0.2).normalized()).toRotationMatrix();
  pose.translation = {5, -20, 40};
  return pose;
}

TEST(ShapeGuess, RecoversPoseAndModeFromPlacedPoints) {
  const ShapeModel model = smallModel();
  Eigen::VectorXd b(1);
  b << 12.0;
  const Eigen::Matrix3Xd truth = somePose().apply(model.shape(b));
  LandmarkSet placed(kPoints, 3);
  for (int i = 0; i < kPoints; i += 3) placed.set(i, Eigen::Vector3d(truth.col(i)));

  const ShapeGuess guess = guessShape(model, placed, Eigen::AlignedBox3d());
  ASSERT_TRUE(guess.fromPlacedPoints);
  for (int i = 0; i < kPoints; ++i) {
    EXPECT_LT((guess.points.col(i) - truth.col(i)).norm(), 0.5) << "point " << i;
  }
}

TEST(ShapeGuess, FewerThanThreePointsGiveTheFrontalGuessInTheBounds) {
  const ShapeModel model = smallModel();
  LandmarkSet placed(kPoints, 3);
  placed.set(0, Eigen::Vector3d(1, 2, 3));
  const Eigen::AlignedBox3d bounds(Eigen::Vector3d(-100, -200, -90),
                                   Eigen::Vector3d(120, 140, 110));

  const ShapeGuess guess = guessShape(model, placed, bounds);
  EXPECT_FALSE(guess.fromPlacedPoints);
  const Eigen::Vector3d low = guess.points.rowwise().minCoeff();
  const Eigen::Vector3d high = guess.points.rowwise().maxCoeff();
  EXPECT_NEAR(0.5 * (low.x() + high.x()), 10.0, 1e-9);
  EXPECT_NEAR(0.5 * (low.y() + high.y()), -30.0, 1e-9);
  EXPECT_NEAR(high.z(), 110.0, 1e-9);
  // The mean at its own size.
  EXPECT_NEAR((high - low).norm(),
              (model.meanShape.rowwise().maxCoeff() - model.meanShape.rowwise().minCoeff()).norm(),
              1e-9);
}

TEST(ShapeGuess, CollinearPointsFallBackAndWrongSizesThrow) {
  const ShapeModel model = smallModel();
  LandmarkSet placed(kPoints, 3);
  for (int i = 0; i < 4; ++i) placed.set(i, Eigen::Vector3d(i, 0, 0));
  EXPECT_FALSE(guessShape(model, placed,
                          Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()))
                   .fromPlacedPoints);
  EXPECT_THROW(guessShape(model, LandmarkSet(5, 3), Eigen::AlignedBox3d()), Error);
}

}  // namespace
}  // namespace clm3d
