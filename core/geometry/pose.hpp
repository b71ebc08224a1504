// The 7-parameter head pose of the thesis (appendix A.1.1): translation (Tx, Ty, Tz), uniform
// scale S and rotations pitch (theta, about x), yaw (phi, about y), roll (gamma, about z).
// Model coordinates: millimetres, +x = subject's left, +y = up, +z = out of the face, origin at
// landmark 1 (between the eyes), which is the centre of rotation.
// Eye coordinates (OpenGL): camera at the origin looking down -z, +y up; a face in front of the
// camera has Tz < 0.
// Composition (column vectors): p_eye = T + S * Rx(pitch) * Ry(yaw) * Rz(roll) * p_model, i.e. the
// thesis's V = T.S.R_theta.R_phi.R_gamma read as an OpenGL matrix stack.
// Signs (right-hand rule): positive yaw turns the nose towards +x (the subject turns to their
// left and shows their right cheek); positive pitch turns the nose down; positive roll turns +x
// towards +y (counter-clockwise in the image).
#pragma once

#include <Eigen/Core>

namespace clm3d {

struct Pose {
  Eigen::Vector3d translation{0.0, 0.0, -1000.0};  // eye coordinates, millimetres
  double scale = 1.0;
  double pitch = 0.0;  // radians
  double yaw = 0.0;    // radians
  double roll = 0.0;   // radians

  static Pose fromDegrees(double pitchDeg, double yawDeg, double rollDeg,
                          const Eigen::Vector3d& translation = {0.0, 0.0, -1000.0},
                          double scale = 1.0);

  Eigen::Matrix3d rotation() const;  // Rx(pitch) * Ry(yaw) * Rz(roll)
  // The 4x4 model-to-eye matrix (column-vector convention), the thesis's V.
  Eigen::Matrix4d viewMatrix() const;
  Eigen::Vector3d toEye(const Eigen::Vector3d& model) const;
  // Applies toEye to each column.
  Eigen::Matrix3Xd toEye(const Eigen::Matrix3Xd& model) const;
};

double degrees(double radians);
double radians(double degrees);

}  // namespace clm3d
