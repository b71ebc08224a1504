#include "core/model/detail/shape_guess.hpp"

#include <Eigen/Dense>
#include <string>

#include "core/common/error.hpp"
#include "core/geometry/procrustes.hpp"

namespace clm3d {

namespace {

ShapeGuess frontalGuess(const ShapeModel& model, const Eigen::AlignedBox3d& bounds) {
  const Eigen::Matrix3Xd& mean = model.meanShape;
  const Eigen::Vector3d low = mean.rowwise().minCoeff();
  const Eigen::Vector3d high = mean.rowwise().maxCoeff();
  const Eigen::Vector3d centre = bounds.center();
  const Eigen::Vector3d shift(centre.x() - 0.5 * (low.x() + high.x()),
                              centre.y() - 0.5 * (low.y() + high.y()), bounds.max().z() - high.z());
  return {mean.colwise() + shift, false};
}

// The mode weights that best explain the placed points (in model coordinates), with a small
// ridge so that few points cannot drive the weights far, then clamped to the model's limits.
Eigen::VectorXd fitModes(const ShapeModel& model, const Eigen::Matrix3Xd& inModel,
                         const std::vector<bool>& use) {
  const int k = model.modeCount();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(k);
  if (k == 0) return b;
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(k, k);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(k);
  for (int i = 0; i < model.pointCount(); ++i) {
    if (!use[i]) continue;
    const Eigen::MatrixXd rows = model.modes.middleRows(3 * i, 3);
    const Eigen::Vector3d residual = inModel.col(i) - model.meanShape.col(i);
    normal += rows.transpose() * rows;
    rhs += rows.transpose() * residual;
  }
  constexpr double kNoiseMm2 = 1.0;  // placement noise variance against the modes' variances
  for (int m = 0; m < k; ++m) normal(m, m) += kNoiseMm2 / std::max(model.variances(m), 1e-9);
  b = normal.ldlt().solve(rhs);
  model.clamp(b);
  return b;
}

}  // namespace

ShapeGuess guessShape(const ShapeModel& model, const LandmarkSet& placed,
                      const Eigen::AlignedBox3d& bounds) {
  if (placed.size() != model.pointCount()) {
    throw Error("guessShape: " + std::to_string(placed.size()) +
                " landmarks, the shape model has " + std::to_string(model.pointCount()));
  }
  if (placed.presentCount() < 3) return frontalGuess(model, bounds);
  const Eigen::Matrix3Xd target = placed.matrix();
  const std::vector<bool> use = placed.presentMask();
  Eigen::Matrix3Xd shape = model.meanShape;
  Similarity3 toScan;
  try {
    for (int round = 0; round < 10; ++round) {
      toScan = alignSimilarity(shape, target, use);
      shape = model.shape(fitModes(model, toScan.inverse().apply(target), use));
    }
    toScan = alignSimilarity(shape, target, use);
  } catch (const Error&) {
    return frontalGuess(model, bounds);  // the placed points lie on a line
  }
  return {toScan.apply(shape), true};
}

}  // namespace clm3d
