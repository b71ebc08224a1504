#include "core/refine/training_starts.hpp"

#include <cmath>

namespace clm3d {

Eigen::Matrix2Xd perturbedPoints(const Eigen::Matrix2Xd& truth, double eyeDistance,
                                 const StartPerturbation& perturbation, std::mt19937_64& random) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const double scale = std::exp(perturbation.scale * normal(random));
  const double roll = perturbation.roll * normal(random);
  const Eigen::Vector2d shift =
      perturbation.shift * eyeDistance * Eigen::Vector2d(normal(random), normal(random));
  const Eigen::Vector2d centre = truth.rowwise().mean();
  const double c = std::cos(roll) * scale, s = std::sin(roll) * scale;
  Eigen::Matrix2Xd start(2, truth.cols());
  for (Eigen::Index i = 0; i < truth.cols(); ++i) {
    const Eigen::Vector2d d = truth.col(i) - centre;
    const Eigen::Vector2d own =
        perturbation.jitter * eyeDistance * Eigen::Vector2d(normal(random), normal(random));
    start.col(i) =
        centre + shift + Eigen::Vector2d(c * d.x() - s * d.y(), s * d.x() + c * d.y()) + own;
  }
  return start;
}

double meanPointError(const Eigen::Matrix2Xd& points, const Eigen::Matrix2Xd& truth,
                      double eyeDistance) {
  return (points - truth).colwise().norm().mean() / eyeDistance;
}

}  // namespace clm3d
