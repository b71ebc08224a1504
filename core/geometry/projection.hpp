// Projection of 3D model points to 2D pixels through a pose and a camera: the one path every
// stage (rendering, training, fitting, synthetic ground truth) uses, so they agree to the pixel.
#pragma once

#include <Eigen/Core>

#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"

namespace clm3d {

Eigen::Vector2d projectPoint(const Eigen::Vector3d& model, const Pose& pose, const Camera& camera);
// Columns are points.
Eigen::Matrix2Xd projectPoints(const Eigen::Matrix3Xd& model, const Pose& pose,
                               const Camera& camera);

// The distance (Tz < 0) at which an object of the given radius (model units, after pose scale)
// fills `fill` (0..1) of the image's smaller side.
double distanceToFit(double radius, const Camera& camera, double fill);

}  // namespace clm3d
