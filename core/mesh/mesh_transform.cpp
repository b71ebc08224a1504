#include "core/mesh/mesh_transform.hpp"

#include <cmath>

#include "core/common/error.hpp"

namespace clm3d {

void transformMesh(TexturedMesh& mesh, const Eigen::Matrix3d& rotation,
                   const Eigen::Vector3d& translation) {
  const Eigen::Matrix3f r = rotation.cast<float>();
  const Eigen::Vector3f t = translation.cast<float>();
  for (auto& p : mesh.positions) p = r * p + t;
  for (auto& n : mesh.normals) n = (r * n).normalized();
}

Eigen::Matrix3d axesToModelRotation(const Eigen::Vector3d& up, const Eigen::Vector3d& front) {
  if (up.norm() == 0.0 || front.norm() == 0.0 ||
      std::abs(up.normalized().dot(front.normalized())) > 1e-6) {
    throw Error("mesh axes: the up and front axes must be perpendicular");
  }
  Eigen::Matrix3d modelInFile;  // columns: the model's x, y, z axes in file coordinates
  modelInFile.col(1) = up.normalized();
  modelInFile.col(2) = front.normalized();
  modelInFile.col(0) = modelInFile.col(1).cross(modelInFile.col(2));
  return modelInFile.transpose();
}

Eigen::Matrix3d eyeLevelRotation(const Eigen::Vector3d& leftEyeCentre,
                                 const Eigen::Vector3d& rightEyeCentre, const Eigen::Vector3d& up) {
  const Eigen::Vector3d eyeLine = leftEyeCentre - rightEyeCentre;
  if (!(eyeLine.norm() > 0.0)) throw Error("eye levelling: the eye centres coincide");
  const Eigen::Vector3d x = eyeLine.normalized();
  const Eigen::Vector3d upAcross = up - up.dot(x) * x;
  if (upAcross.norm() < 1e-3 * up.norm()) {
    throw Error("eye levelling: the eye line is along the up axis");
  }
  Eigen::Matrix3d modelInFile;
  modelInFile.col(0) = x;
  modelInFile.col(1) = upAcross.normalized();
  modelInFile.col(2) = x.cross(modelInFile.col(1));
  return modelInFile.transpose();
}

}  // namespace clm3d
