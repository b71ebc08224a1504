#include "core/geometry/camera.hpp"

#include <cmath>

#include "core/common/error.hpp"
#include "core/geometry/pose.hpp"

namespace clm3d {

Camera Camera::fromVerticalFov(int width, int height, double verticalFovDegrees, double near,
                               double far) {
  if (width <= 0 || height <= 0) throw Error("camera: image size must be positive");
  if (!(verticalFovDegrees > 0.0 && verticalFovDegrees < 180.0)) {
    throw Error("camera: vertical field of view must be in (0, 180) degrees");
  }
  if (!(near > 0.0 && far > near)) throw Error("camera: need 0 < near < far");
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.near = near;
  camera.far = far;
  camera.top = near * std::tan(radians(verticalFovDegrees) / 2.0);
  camera.right = camera.top * static_cast<double>(width) / static_cast<double>(height);
  return camera;
}

double Camera::focalX() const {
  return near / right * width / 2.0;
}
double Camera::focalY() const {
  return near / top * height / 2.0;
}

Eigen::Matrix4d Camera::projectionMatrix() const {
  // Eq. A.10 with r = -l and t = -b (eq. A.11), so A = B = 0.
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = near / right;
  m(1, 1) = near / top;
  m(2, 2) = -(far + near) / (far - near);
  m(2, 3) = -2.0 * far * near / (far - near);
  m(3, 2) = -1.0;
  return m;
}

Eigen::Vector2d Camera::eyeToPixel(const Eigen::Vector3d& eye) const {
  // Eq. A.12 (the camera looks down -z, so divide by -z), then the viewport with pixel centres
  // at integer coordinates and y pointing down.
  const double xn = near * eye.x() / (right * -eye.z());
  const double yn = near * eye.y() / (top * -eye.z());
  return {(xn + 1.0) * 0.5 * width - 0.5, (1.0 - yn) * 0.5 * height - 0.5};
}

Eigen::Vector3d Camera::pixelToEye(const Eigen::Vector2d& pixel, double depth) const {
  const double xn = (pixel.x() + 0.5) * 2.0 / width - 1.0;
  const double yn = 1.0 - (pixel.y() + 0.5) * 2.0 / height;
  return {xn * right * depth / near, yn * top * depth / near, -depth};
}

}  // namespace clm3d
