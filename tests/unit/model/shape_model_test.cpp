// buildShapeModel: Procrustes removes pose, a known mode is recovered, missing points are imputed,
// mirroring makes the mean symmetric, the 2D baseline stays in the plane; clamp.
#include "core/model/shape_model.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "core/common/error.hpp"
#include "core/geometry/procrustes.hpp"

namespace clm3d {
namespace {

// A rough upright 25-point face (mm, +y up, +z out of the face), thesis25 order.
Eigen::Matrix3Xd baseFace() {
  Eigen::Matrix3Xd face(3, 25);
  const double points[25][3] = {
      {0, 0, 0},       {-45, -2, -12}, {45, -2, -12},  {-50, 12, -10},  {-15, 14, 0},
      {15, 14, 0},     {50, 12, -10},  {-31, -2, -5},  {-17, -2, -4},   {17, -2, -4},
      {31, -2, -5},    {0, -35, 22},   {-16, -42, 5},  {16, -42, 5},    {-25, -65, -2},
      {25, -65, -2},   {0, -58, 8},    {0, -72, 6},    {-72, -40, -80}, {-55, -50, -30},
      {-40, -90, -30}, {0, -105, 0},   {40, -90, -30}, {55, -50, -30},  {72, -40, -80}};
  for (int i = 0; i < 25; ++i)
    face.col(i) = Eigen::Vector3d(points[i][0], points[i][1], points[i][2]);
  return face;
}

// Mouth opening: lower lip and chin points move down.
Eigen::Matrix3Xd mouthOpening() {
  Eigen::Matrix3Xd d = Eigen::Matrix3Xd::Zero(3, 25);
  for (const int i : {17, 20, 21, 22}) d(1, i) = -1.0;
  d(1, 14) = d(1, 15) = -0.4;
  return d;
}

LandmarkSet toSet(const Eigen::Matrix3Xd& points) {
  LandmarkSet set(static_cast<int>(points.cols()), 3);
  for (int i = 0; i < points.cols(); ++i) set.set(i, Eigen::Vector3d(points.col(i)));
  return set;
}

Eigen::Matrix3Xd posed(const Eigen::Matrix3Xd& points, double angle, const Eigen::Vector3d& axis,
                       double scale, const Eigen::Vector3d& shift) {
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  return ((scale * rotation * points).colwise() + shift).eval();
}

double rmsSize(const Eigen::Matrix3Xd& points) {
  const Eigen::Matrix3Xd centred = points.colwise() - points.rowwise().mean();
  return std::sqrt(centred.squaredNorm() / static_cast<double>(points.cols()));
}

// Shapes with two independent modes (mouth, eye spacing), each posed at random.
std::vector<Eigen::Matrix3Xd> twoModeShapes(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Matrix3Xd eyes = Eigen::Matrix3Xd::Zero(3, 25);
  for (const int i : {1, 3, 4, 7, 8}) eyes(0, i) = -1.0;
  for (const int i : {2, 5, 6, 9, 10}) eyes(0, i) = 1.0;
  std::vector<Eigen::Matrix3Xd> shapes;
  for (int s = 0; s < count; ++s) {
    const Eigen::Matrix3Xd shape =
        baseFace() + 3.0 * normal(random) * mouthOpening() + 1.5 * normal(random) * eyes;
    shapes.push_back(posed(shape, 0.3 * normal(random),
                           Eigen::Vector3d(normal(random), normal(random), 1),
                           1.0 + 0.1 * normal(random), Eigen::Vector3d(normal(random), 5, 500)));
  }
  return shapes;
}

TEST(ShapeModel, AlignmentRemovesPose) {
  const Eigen::Matrix3Xd face = baseFace();
  std::vector<LandmarkSet> shapes = {toSet(face)};
  const double scales[] = {1.0, 2.0, 0.5, 1.5};
  for (int k = 1; k < 4; ++k) {
    shapes.push_back(toSet(posed(face, 0.4 * k, Eigen::Vector3d(1, k, 2), scales[k],
                                 Eigen::Vector3d(10 * k, -3, 400))));
  }
  const ShapeModel model = buildShapeModel(shapes, Scheme::thesis25());
  EXPECT_LT(model.variances.sum(), 1e-12 * rmsSize(face) * rmsSize(face));
  // Mean: the first shape's orientation, landmark 1 at the origin, the mean size (1.25x).
  const Eigen::Matrix3Xd expected = (face.colwise() - face.col(0)) * 1.25;
  EXPECT_LT((model.meanShape - expected).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(ShapeModel, RecoversAKnownMode) {
  // Small mouth openings (sd 2 mm), randomly posed except the first shape, whose upright frame
  // the model keeps.
  std::vector<LandmarkSet> shapes;
  std::mt19937 random(4);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int s = 0; s < 30; ++s) {
    const Eigen::Matrix3Xd shape = baseFace() + 2.0 * normal(random) * mouthOpening();
    shapes.push_back(s == 0 ? toSet(shape)
                            : toSet(posed(shape, 0.2 * normal(random), Eigen::Vector3d(0, 1, 0.3),
                                          1.0 + 0.2 * normal(random), Eigen::Vector3d(0, 0, 600))));
  }
  const ShapeModel model = buildShapeModel(shapes, Scheme::thesis25());
  ASSERT_EQ(model.modeCount(), 1);
  ASSERT_EQ(model.modes.rows(), 75);
  EXPECT_NEAR(model.modes.col(0).norm(), 1.0, 1e-12);
  // The mode is the mouth opening less the similarity motion Procrustes takes out of it.
  const double epsilon = 1e-4;
  const Eigen::Matrix3Xd base = baseFace();
  const Eigen::Matrix3Xd opened = base + epsilon * mouthOpening();
  const Eigen::Matrix3Xd tangent = (alignSimilarity(opened, base).apply(opened) - base) / epsilon;
  const Eigen::VectorXd expected = Eigen::Map<const Eigen::VectorXd>(tangent.data(), 75);
  EXPECT_GT(std::abs(model.modes.col(0).dot(expected.normalized())), 0.99);
  // Every training shape is reproduced by the model after alignment.
  for (const LandmarkSet& shape : shapes) {
    const Eigen::Matrix3Xd points = shape.matrix();
    const Eigen::Matrix3Xd aligned = alignSimilarity(points, model.meanShape).apply(points);
    const Eigen::Matrix3Xd residual = aligned - model.meanShape;
    const Eigen::VectorXd d = Eigen::Map<const Eigen::VectorXd>(residual.data(), 75);
    const Eigen::VectorXd b = model.modes.transpose() * d;
    EXPECT_LT((d - model.modes * b).norm(), 0.1 * d.norm() + 1e-6);
  }
  EXPECT_NEAR(model.meanShape.col(0).norm(), 0.0, 1e-9);
}

TEST(ShapeModel, ImputesMissingPoints) {
  const std::vector<Eigen::Matrix3Xd> shapes = twoModeShapes(40, 9);
  std::vector<LandmarkSet> full, partial;
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    full.push_back(toSet(shapes[s]));
    LandmarkSet gappy = toSet(shapes[s]);
    if (s % 3 == 1) gappy.setMissing(static_cast<int>(18 + s % 7));  // jaw points
    if (s % 4 == 2) gappy.setMissing(static_cast<int>(s % 25));
    partial.push_back(gappy);
  }
  const ShapeModel reference = buildShapeModel(full, Scheme::thesis25());
  const ShapeModel model = buildShapeModel(partial, Scheme::thesis25());
  ASSERT_EQ(reference.modeCount(), 2);
  ASSERT_EQ(model.modeCount(), 2);
  const double meanError = (model.meanShape - reference.meanShape).cwiseAbs().maxCoeff();
  // Not exact: a shape with gaps is aligned on its present points only (measured 0.015 mm).
  EXPECT_LT(meanError, 2e-3 * rmsSize(reference.meanShape));
  const Eigen::MatrixXd overlap = model.modes.transpose() * reference.modes;  // same subspace
  EXPECT_NEAR(std::abs(overlap.determinant()), 1.0, 1e-3);
}

TEST(ShapeModel, MirrorMakesTheMeanSymmetric) {
  const Scheme& scheme = Scheme::thesis25();
  std::vector<LandmarkSet> shapes;
  for (const Eigen::Matrix3Xd& shape : twoModeShapes(10, 2)) {
    Eigen::Matrix3Xd lopsided = shape;
    lopsided.col(14) += Eigen::Vector3d(-6, 4, 0);  // the left mouth corner pulled up
    shapes.push_back(toSet(lopsided));
  }
  const auto asymmetry = [&](const Eigen::Matrix3Xd& mean) {
    Eigen::Matrix3Xd mirrored(3, 25);
    for (int i = 0; i < 25; ++i) {
      mirrored.col(i) = mean.col(scheme.mirrorOf(i));
      mirrored(0, i) = -mirrored(0, i);
    }
    return rmsDistance(alignSimilarity(mirrored, mean).apply(mirrored), mean);
  };
  const ShapeModel plain = buildShapeModel(shapes, scheme);
  ShapeModelSettings settings;
  settings.mirror = true;
  const ShapeModel mirrored = buildShapeModel(shapes, scheme, settings);
  EXPECT_GT(asymmetry(plain.meanShape), 0.5);
  EXPECT_LT(asymmetry(mirrored.meanShape), 1e-6);
  // The mirrored copies add the left-right asymmetry as variation: more total variance.
  EXPECT_GT(mirrored.variances.sum(), plain.variances.sum());
}

TEST(ShapeModel, TwoDimensionalBaselineStaysInThePlane) {
  std::vector<LandmarkSet> shapes;
  for (const Eigen::Matrix3Xd& shape : twoModeShapes(12, 5)) shapes.push_back(toSet(shape));
  ShapeModelSettings settings;
  settings.dims = 2;
  const ShapeModel model = buildShapeModel(shapes, Scheme::thesis25(), settings);
  EXPECT_EQ(model.dims, 2);
  EXPECT_EQ(model.meanShape.row(2).cwiseAbs().maxCoeff(), 0.0);
  for (Eigen::Index i = 0; i < 25; ++i) {
    EXPECT_LT(model.modes.row(3 * i + 2).cwiseAbs().maxCoeff(), 1e-12);
  }
  EXPECT_GE(model.modeCount(), 1);
}

TEST(ShapeModel, RejectsTooFewOrWrongSizedShapes) {
  const Scheme& scheme = Scheme::thesis25();
  EXPECT_THROW(buildShapeModel({toSet(baseFace())}, scheme), Error);
  LandmarkSet sparse(25, 3);
  sparse.set(0, Eigen::Vector3d(0, 0, 0));
  sparse.set(1, Eigen::Vector3d(1, 0, 0));
  EXPECT_THROW(buildShapeModel({toSet(baseFace()), sparse}, scheme), Error);
  EXPECT_THROW(buildShapeModel({toSet(baseFace()), LandmarkSet(5, 3)}, scheme), Error);
  ShapeModelSettings settings;
  settings.dims = 4;
  EXPECT_THROW(buildShapeModel({toSet(baseFace()), toSet(baseFace())}, scheme, settings), Error);
}

TEST(ShapeModel, ClampKeepsParametersWithinTheLimit) {
  ShapeModel model;
  model.meanShape = Eigen::Matrix3Xd::Zero(3, 2);
  model.modes = Eigen::MatrixXd::Identity(6, 2);
  model.variances = Eigen::Vector2d(4.0, 9.0);
  model.limitSd = 3.0;
  Eigen::VectorXd b(2);
  b << 7.0, -20.0;
  model.clamp(b);
  EXPECT_EQ(b, Eigen::Vector2d(6.0, -9.0));
  b << -1.0, 2.0;
  model.clamp(b);
  EXPECT_EQ(b, Eigen::Vector2d(-1.0, 2.0));
  Eigen::VectorXd wrong(3);
  EXPECT_THROW(model.clamp(wrong), Error);
  const Eigen::Matrix3Xd shape = model.shape(Eigen::Vector2d(1.0, 2.0));
  EXPECT_EQ(shape(0, 0), 1.0);
  EXPECT_EQ(shape(1, 0), 2.0);
}

}  // namespace
}  // namespace clm3d
