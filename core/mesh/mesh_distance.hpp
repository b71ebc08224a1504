// Distances from points to a mesh surface: to check that landmarks lie on a scan or a generated
// head, and (in the studio) to snap a clicked or dragged landmark onto the surface.
#pragma once

#include <Eigen/Core>

#include "core/mesh/textured_mesh.hpp"

namespace clm3d {

// The point of the triangle (a, b, c) nearest to p (on a face, an edge or a corner).
Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c);

struct SurfacePoint {
  Eigen::Vector3d point;  // nearest point of the surface
  double distance = 0.0;
  int triangle = -1;  // index into mesh.triangles; -1 for a mesh without triangles
};

// The surface point of the mesh nearest to p: brute force over the triangles with a
// bounding-sphere rejection, fine for checks and interactive picks (not for per-frame use).
SurfacePoint nearestSurfacePoint(const TexturedMesh& mesh, const Eigen::Vector3d& p);

}  // namespace clm3d
