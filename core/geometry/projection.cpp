#include "core/geometry/projection.hpp"

#include <algorithm>

namespace clm3d {

Eigen::Vector2d projectPoint(const Eigen::Vector3d& model, const Pose& pose, const Camera& camera) {
  return camera.eyeToPixel(pose.toEye(model));
}

Eigen::Matrix2Xd projectPoints(const Eigen::Matrix3Xd& model, const Pose& pose,
                               const Camera& camera) {
  const Eigen::Matrix3Xd eye = pose.toEye(model);
  Eigen::Matrix2Xd pixels(2, eye.cols());
  for (Eigen::Index i = 0; i < eye.cols(); ++i) pixels.col(i) = camera.eyeToPixel(eye.col(i));
  return pixels;
}

double distanceToFit(double radius, const Camera& camera, double fill) {
  // An object of radius r at distance d spans 2 r f / d pixels; solve for d.
  const double focal = std::min(camera.focalX(), camera.focalY());
  const double side = std::min(camera.width, camera.height);
  return -(2.0 * radius * focal / (fill * side));
}

}  // namespace clm3d
