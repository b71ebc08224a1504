// The mid-sagittal (left-right symmetry) plane of a face estimated from whichever landmarks are
// placed, and reflection across it: the annotator suggests where the mirror image of a placed
// landmark lies, which only needs the pairs and mid-line points placed so far.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace clm3d {

struct Plane3 {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // unit length
  double offset = 0.0;                                // normal . p = offset on the plane

  double signedDistance(const Eigen::Vector3d& p) const { return normal.dot(p) - offset; }
  Eigen::Vector3d reflect(const Eigen::Vector3d& p) const {
    return p - 2.0 * signedDistance(p) * normal;
  }
};

// points: one column per landmark; present: which columns hold a point; mirrorOf: each
// landmark's mirror index (itself for a mid-line point), as Scheme::mirrorOf gives.
// The normal is the main direction of the left-minus-right vectors of fully placed pairs; without
// such a pair, the least-spread direction of >= 3 placed mid-line points that span a plane;
// failing that, fallbackNormal (the model's +x). The plane passes through the mean of the pairs'
// midpoints and the mid-line points. nullopt when neither a full pair nor a mid-line point is
// placed (nothing locates the plane).
std::optional<Plane3> estimateSymmetryPlane(
    const Eigen::Matrix3Xd& points, const std::vector<bool>& present,
    const std::vector<int>& mirrorOf,
    const Eigen::Vector3d& fallbackNormal = Eigen::Vector3d::UnitX());

}  // namespace clm3d
