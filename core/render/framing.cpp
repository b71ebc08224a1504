#include "core/render/framing.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/common/error.hpp"
#include "core/geometry/projection.hpp"

namespace clm3d {

double meshRadius(const TexturedMesh& mesh, const Eigen::Vector3d& about) {
  double radius = 0.0;
  for (const auto& p : mesh.positions) radius = std::max(radius, (p.cast<double>() - about).norm());
  return radius;
}

// A few fixed-point steps: perspective makes the span slightly non-linear in the distance.
Eigen::Vector3d frameMesh(const TexturedMesh& mesh, const Pose& rotation, const Camera& camera,
                          double fill) {
  const std::size_t stride = std::max<std::size_t>(1, mesh.vertexCount() / 20000);
  const double radius = meshRadius(mesh);
  if (!(radius > 0.0)) throw Error("framing: the mesh has no extent");
  Eigen::Vector3d translation(0.0, 0.0, distanceToFit(radius, camera, fill) - radius);
  for (int iteration = 0; iteration < 8; ++iteration) {
    Pose pose = rotation;
    pose.translation = translation;
    Eigen::AlignedBox2d box;
    for (std::size_t i = 0; i < mesh.vertexCount(); i += stride) {
      box.extend(projectPoint(mesh.positions[i].cast<double>(), pose, camera));
    }
    const Eigen::Vector2d centre(0.5 * (camera.width - 1), 0.5 * (camera.height - 1));
    const Eigen::Vector2d offset = box.center() - centre;
    const double span = std::max(box.sizes().x() / camera.width, box.sizes().y() / camera.height);
    const double depth = -translation.z();
    translation.x() -= offset.x() * depth / camera.focalX();
    translation.y() += offset.y() * depth / camera.focalY();
    // Move so the span becomes `fill`; nearer points grow faster, hence the iteration.
    // Never so close that part of the head is behind the camera.
    translation.z() = std::min(-(depth * span / fill), -(1.1 * radius + camera.near));
    if (std::abs(span - fill) < 1e-3 && offset.norm() < 0.25) break;
  }
  return translation;
}

}  // namespace clm3d
