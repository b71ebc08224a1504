#include "core/geometry/pose.hpp"

#include <Eigen/Geometry>
#include <numbers>

namespace clm3d {

double degrees(double radiansValue) {
  return radiansValue * 180.0 / std::numbers::pi;
}
double radians(double degreesValue) {
  return degreesValue * std::numbers::pi / 180.0;
}

Pose Pose::fromDegrees(double pitchDeg, double yawDeg, double rollDeg,
                       const Eigen::Vector3d& translation, double scale) {
  Pose pose;
  pose.translation = translation;
  pose.scale = scale;
  pose.pitch = radians(pitchDeg);
  pose.yaw = radians(yawDeg);
  pose.roll = radians(rollDeg);
  return pose;
}

Eigen::Matrix3d Pose::rotation() const {
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  return (AngleAxisd(pitch, Vector3d::UnitX()) * AngleAxisd(yaw, Vector3d::UnitY()) *
          AngleAxisd(roll, Vector3d::UnitZ()))
      .toRotationMatrix();
}

Eigen::Matrix4d Pose::viewMatrix() const {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.topLeftCorner<3, 3>() = scale * rotation();
  view.topRightCorner<3, 1>() = translation;
  return view;
}

Eigen::Vector3d Pose::toEye(const Eigen::Vector3d& model) const {
  return scale * (rotation() * model) + translation;
}

Eigen::Matrix3Xd Pose::toEye(const Eigen::Matrix3Xd& model) const {
  return ((scale * rotation()) * model).colwise() + translation;
}

}  // namespace clm3d
