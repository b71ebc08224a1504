// Automatic framing: where to put a mesh in front of a camera so that its projection is centred
// and spans a chosen share of the image, for renders a person looks at (clm3d render, previews).
// Training renders are framed on the landmarks instead (core/train/training_sample.hpp).
#pragma once

#include <Eigen/Core>

#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"
#include "core/mesh/textured_mesh.hpp"

namespace clm3d {

// The distance from `about` (model coordinates) to the mesh's farthest vertex: the radius of the
// sphere that holds the mesh, for framing and for a camera's clipping planes. 0 for no vertices.
double meshRadius(const TexturedMesh& mesh, const Eigen::Vector3d& about = Eigen::Vector3d::Zero());

// The translation (eye coordinates) for `rotation`'s angles and scale that centres the mesh's
// projection and makes its larger side span `fill` of the image; never so close that part of the
// mesh is behind the camera. Throws Error for a mesh without extent.
Eigen::Vector3d frameMesh(const TexturedMesh& mesh, const Pose& rotation, const Camera& camera,
                          double fill);

}  // namespace clm3d
