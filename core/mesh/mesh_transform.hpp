// Rigid changes of a mesh's frame, to bring a scan into the model convention (+x subject's left,
// +y up, +z out of the face, millimetres) before rendering: from the file's axes, or levelled on
// the subject's eyes so that yaw 0 / roll 0 mean a frontal, upright face.
#pragma once

#include <Eigen/Core>

#include "core/mesh/textured_mesh.hpp"

namespace clm3d {

// p' = rotation * p + translation for every position; normals are rotated.
void transformMesh(TexturedMesh& mesh, const Eigen::Matrix3d& rotation,
                   const Eigen::Vector3d& translation = Eigen::Vector3d::Zero());

// The rotation taking file coordinates to model coordinates when the file's up and front
// (out of the face) axes are `up` and `front`. Throws Error unless they are perpendicular.
Eigen::Matrix3d axesToModelRotation(const Eigen::Vector3d& up, const Eigen::Vector3d& front);

// The rotation taking file coordinates to model coordinates with +x along the line from the
// subject's right eye centre to the left one (removing the scan's own yaw and roll) and +y the
// file's up axis made perpendicular to it (keeping the scan's pitch). Throws Error if the eyes
// coincide or the eye line is along `up`.
Eigen::Matrix3d eyeLevelRotation(const Eigen::Vector3d& leftEyeCentre,
                                 const Eigen::Vector3d& rightEyeCentre, const Eigen::Vector3d& up);

}  // namespace clm3d
