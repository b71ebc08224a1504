#include "core/geometry/similarity2.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace clm3d {

Eigen::Vector2d Similarity2::apply(const Eigen::Vector2d& source) const {
  return scale * (Eigen::Rotation2Dd(angle) * source) + translation;
}

Eigen::Vector2d Similarity2::inverse(const Eigen::Vector2d& target) const {
  return Eigen::Rotation2Dd(-angle) * ((target - translation) / scale);
}

Eigen::Matrix2Xd Similarity2::apply(const Eigen::Matrix2Xd& source) const {
  return ((scale * Eigen::Rotation2Dd(angle).toRotationMatrix()) * source).colwise() + translation;
}

Eigen::Matrix2Xd Similarity2::inverse(const Eigen::Matrix2Xd& target) const {
  return (Eigen::Rotation2Dd(-angle).toRotationMatrix() / scale) * (target.colwise() - translation);
}

Similarity2 alignSimilarity2(const Eigen::Matrix2Xd& source, const Eigen::Matrix2Xd& target) {
  const Eigen::Vector2d ms = source.rowwise().mean();
  const Eigen::Vector2d mt = target.rowwise().mean();
  const Eigen::Matrix2Xd s = source.colwise() - ms;
  const Eigen::Matrix2Xd t = target.colwise() - mt;
  const double a = (s.row(0).cwiseProduct(t.row(0)) + s.row(1).cwiseProduct(t.row(1))).sum();
  const double b = (s.row(0).cwiseProduct(t.row(1)) - s.row(1).cwiseProduct(t.row(0))).sum();
  const double norm = s.squaredNorm();
  Similarity2 result;
  if (!(norm > 0.0)) return result;
  result.scale = std::hypot(a, b) / norm;
  result.angle = std::atan2(b, a);
  result.translation = mt - result.scale * (Eigen::Rotation2Dd(result.angle) * ms);
  return result;
}

}  // namespace clm3d
