#include "core/geometry/symmetry_plane.hpp"

#include <Eigen/Eigenvalues>
#include <stdexcept>

namespace clm3d {

std::optional<Plane3> estimateSymmetryPlane(const Eigen::Matrix3Xd& points,
                                            const std::vector<bool>& present,
                                            const std::vector<int>& mirrorOf,
                                            const Eigen::Vector3d& fallbackNormal) {
  const int n = static_cast<int>(points.cols());
  if (static_cast<int>(present.size()) != n || static_cast<int>(mirrorOf.size()) != n) {
    throw std::invalid_argument(
        "estimateSymmetryPlane: points, present and mirrorOf differ in size");
  }
  Eigen::Matrix3d pairScatter = Eigen::Matrix3d::Zero();
  std::vector<Eigen::Vector3d> onPlane;  // pair midpoints and mid-line points
  std::vector<Eigen::Vector3d> midline;
  int pairs = 0;
  for (int i = 0; i < n; ++i) {
    if (!present[i]) continue;
    const int j = mirrorOf[i];
    if (j == i) {
      onPlane.push_back(points.col(i));
      midline.push_back(points.col(i));
    } else if (j > i && j < n && present[j]) {
      const Eigen::Vector3d d = points.col(i) - points.col(j);
      pairScatter += d * d.transpose();
      onPlane.push_back(0.5 * (points.col(i) + points.col(j)));
      ++pairs;
    }
  }
  if (onPlane.empty()) return std::nullopt;

  Plane3 plane;
  plane.normal = fallbackNormal.normalized();
  if (pairs > 0) {
    // Scatter is a sum of outer products: its top eigenvector is the dominant pair direction,
    // whatever the sign of each left-minus-right vector.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(pairScatter);
    plane.normal = solver.eigenvectors().col(2).normalized();
  } else if (midline.size() >= 3) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : midline) mean += p;
    mean /= static_cast<double>(midline.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const auto& p : midline) scatter += (p - mean) * (p - mean).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
    // The points span a plane when the two largest spreads are clearly above the smallest.
    if (solver.eigenvalues()(1) > 1e-6 * std::max(solver.eigenvalues()(2), 1e-12)) {
      plane.normal = solver.eigenvectors().col(0).normalized();
    }
  }
  if (plane.normal.dot(fallbackNormal) < 0) plane.normal = -plane.normal;
  double offset = 0.0;
  for (const auto& p : onPlane) offset += plane.normal.dot(p);
  plane.offset = offset / static_cast<double>(onPlane.size());
  return plane;
}

}  // namespace clm3d
