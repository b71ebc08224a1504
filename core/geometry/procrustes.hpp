// Similarity Procrustes in 3D (scale, rotation, translation; Umeyama's least-squares solution),
// used to align training shapes to their mean and to estimate a pose from points.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace clm3d {

struct Similarity3 {
  double scale = 1.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const {
    return scale * rotation * p + translation;
  }
  Eigen::Matrix3Xd apply(const Eigen::Matrix3Xd& points) const;
  Similarity3 inverse() const;
};

// The similarity that maps `source` onto `target` (columns are corresponding points) in the least
// squares sense. `use` selects the correspondences to fit on (empty = all); at least 3
// non-collinear points are needed. With allowScale = false the scale is fixed at 1 (rigid). Throws
// clm3d::Error if the points are degenerate.
Similarity3 alignSimilarity(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                            const std::vector<bool>& use = {}, bool allowScale = true);

// Root mean square distance between corresponding columns (selected by `use`, empty = all).
double rmsDistance(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b,
                   const std::vector<bool>& use = {});

}  // namespace clm3d
