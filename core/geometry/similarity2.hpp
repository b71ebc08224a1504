// A 2D similarity (scale, rotation, translation) and its least-squares fit between two point
// sets (Umeyama in complex form): how the detector's start poses the mean shape on a box's points
// and how the point refiner maps its mean shape onto the current points.
#pragma once

#include <Eigen/Core>

namespace clm3d {

// target = scale * R(angle) * source + translation.
struct Similarity2 {
  double scale = 1.0;
  double angle = 0.0;  // radians
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();

  Eigen::Vector2d apply(const Eigen::Vector2d& source) const;
  Eigen::Vector2d inverse(const Eigen::Vector2d& target) const;
  Eigen::Matrix2Xd apply(const Eigen::Matrix2Xd& source) const;
  Eigen::Matrix2Xd inverse(const Eigen::Matrix2Xd& target) const;
};

// The least-squares similarity taking `source` onto `target` (2 x N each, same N). When the
// source points coincide, the identity (scale 1).
Similarity2 alignSimilarity2(const Eigen::Matrix2Xd& source, const Eigen::Matrix2Xd& target);

}  // namespace clm3d
