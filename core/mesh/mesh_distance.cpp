#include "core/mesh/mesh_distance.hpp"

#include <algorithm>
#include <limits>

namespace clm3d {

Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  // Classify p against the Voronoi regions of the triangle's corners, edges and face, using the
  // projections of p onto the two edges from each corner.
  const Eigen::Vector3d ab = b - a;
  const Eigen::Vector3d ac = c - a;
  const double abAp = ab.dot(p - a);
  const double acAp = ac.dot(p - a);
  if (abAp <= 0.0 && acAp <= 0.0) return a;

  const double abBp = ab.dot(p - b);
  const double acBp = ac.dot(p - b);
  if (abBp >= 0.0 && acBp <= abBp) return b;

  const double abCp = ab.dot(p - c);
  const double acCp = ac.dot(p - c);
  if (acCp >= 0.0 && abCp <= acCp) return c;

  const double edgeC = abAp * acBp - abBp * acAp;  // barycentric weight of c (unnormalised)
  if (edgeC <= 0.0 && abAp >= 0.0 && abBp <= 0.0) return a + ab * (abAp / (abAp - abBp));

  const double edgeB = abCp * acAp - abAp * acCp;  // weight of b
  if (edgeB <= 0.0 && acAp >= 0.0 && acCp <= 0.0) return a + ac * (acAp / (acAp - acCp));

  const double edgeA = abBp * acCp - abCp * acBp;  // weight of a
  if (edgeA <= 0.0 && (acBp - abBp) >= 0.0 && (abCp - acCp) >= 0.0) {
    const double t = (acBp - abBp) / ((acBp - abBp) + (abCp - acCp));
    return b + (c - b) * t;
  }
  const double sum = edgeA + edgeB + edgeC;
  return a + ab * (edgeB / sum) + ac * (edgeC / sum);
}

SurfacePoint nearestSurfacePoint(const TexturedMesh& mesh, const Eigen::Vector3d& p) {
  SurfacePoint best;
  best.point = p;
  best.distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    const Eigen::Vector3d a = mesh.positions[static_cast<std::size_t>(t.x())].cast<double>();
    const Eigen::Vector3d b = mesh.positions[static_cast<std::size_t>(t.y())].cast<double>();
    const Eigen::Vector3d c = mesh.positions[static_cast<std::size_t>(t.z())].cast<double>();
    const Eigen::Vector3d centre = (a + b + c) / 3.0;
    const double radius = std::max({(a - centre).norm(), (b - centre).norm(), (c - centre).norm()});
    if ((p - centre).norm() - radius > best.distance) continue;
    const Eigen::Vector3d q = closestPointOnTriangle(p, a, b, c);
    const double d = (q - p).norm();
    if (d < best.distance) best = {q, d, static_cast<int>(i)};
  }
  return best;
}

}  // namespace clm3d
