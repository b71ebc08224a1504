#include "core/registration/surface_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/mesh/mesh_distance.hpp"

namespace clm3d {
namespace {

constexpr long kMaxCells = 1L << 22;

Eigen::Vector3d corner(const TexturedMesh& mesh, const Eigen::Vector3i& t, int k) {
  return mesh.positions[static_cast<std::size_t>(t[k])].cast<double>();
}

// Barycentric weights of p (a point of the triangle's plane) in the triangle (a, b, c).
Eigen::Vector3d barycentricOf(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                              const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d e0 = b - a, e1 = c - a, d = p - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
  const double d20 = d.dot(e0), d21 = d.dot(e1);
  const double det = d00 * d11 - d01 * d01;
  if (det <= 0.0) return {1.0, 0.0, 0.0};
  const double v = (d11 * d20 - d01 * d21) / det;
  const double w = (d00 * d21 - d01 * d20) / det;
  return {1.0 - v - w, v, w};
}

}  // namespace

SurfaceIndex::SurfaceIndex(const TexturedMesh& mesh) : mesh_(mesh) {
  normals_.assign(mesh.triangles.size(), Eigen::Vector3d::Zero());
  if (mesh.triangles.empty() || mesh.positions.empty()) {
    cellStart_.assign(2, 0);
    return;
  }
  double edgeSum = 0.0;
  Eigen::AlignedBox3d box;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d a = corner(mesh, tri, 0), b = corner(mesh, tri, 1),
                          c = corner(mesh, tri, 2);
    edgeSum += (b - a).norm() + (c - b).norm() + (a - c).norm();
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (n.norm() > 0.0) normals_[t] = n.normalized();
    box.extend(a);
    box.extend(b);
    box.extend(c);
  }
  cell_ = std::max(1e-6, 2.0 * edgeSum / (3.0 * static_cast<double>(mesh.triangles.size())));
  const Eigen::Vector3d extent = box.sizes();
  for (;;) {
    dims_ = ((extent / cell_).array().floor() + 1.0).cast<int>().matrix();
    if (static_cast<long>(dims_.x()) * dims_.y() * dims_.z() <= kMaxCells) break;
    cell_ *= 1.5;
  }
  origin_ = box.min();

  // Two passes (count, then fill) into compressed rows.
  const long cells = static_cast<long>(dims_.x()) * dims_.y() * dims_.z();
  std::vector<int> counts(static_cast<std::size_t>(cells) + 1, 0);
  auto forEachCell = [&](std::size_t t, auto&& visit) {
    if (normals_[t].isZero()) return;
    const auto& tri = mesh.triangles[t];
    Eigen::AlignedBox3d tb;
    for (int k = 0; k < 3; ++k) tb.extend(corner(mesh, tri, k));
    const Eigen::Vector3i lo = cellOf(tb.min()), hi = cellOf(tb.max());
    for (int z = lo.z(); z <= hi.z(); ++z) {
      for (int y = lo.y(); y <= hi.y(); ++y) {
        for (int x = lo.x(); x <= hi.x(); ++x) visit(cellKey(x, y, z));
      }
    }
  };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    forEachCell(t, [&](long key) { ++counts[static_cast<std::size_t>(key) + 1]; });
  }
  for (std::size_t i = 1; i < counts.size(); ++i) counts[i] += counts[i - 1];
  cellStart_ = counts;
  items_.resize(static_cast<std::size_t>(counts.back()));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    forEachCell(t, [&](long key) {
      items_[static_cast<std::size_t>(counts[static_cast<std::size_t>(key)]++)] =
          static_cast<int>(t);
    });
  }
}

long SurfaceIndex::cellKey(long x, long y, long z) const {
  return (z * dims_.y() + y) * dims_.x() + x;
}

Eigen::Vector3i SurfaceIndex::cellOf(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d f = ((p - origin_) / cell_).array().floor();
  Eigen::Vector3i c;
  for (int k = 0; k < 3; ++k) {
    c[k] = static_cast<int>(std::clamp(f[k], -1e6, 1e6));
  }
  return c;
}

std::optional<SurfaceHit> SurfaceIndex::nearest(const Eigen::Vector3d& p,
                                                double maxDistance) const {
  if (items_.empty() || !p.allFinite()) return std::nullopt;
  const Eigen::Vector3i centre = cellOf(p);
  const int rings = static_cast<int>(std::ceil(maxDistance / cell_)) + 1;
  double best = maxDistance;
  SurfaceHit hit;
  bool found = false;
  for (int r = 0; r <= rings; ++r) {
    for (int dz = -r; dz <= r; ++dz) {
      const int z = centre.z() + dz;
      if (z < 0 || z >= dims_.z()) continue;
      for (int dy = -r; dy <= r; ++dy) {
        const int y = centre.y() + dy;
        if (y < 0 || y >= dims_.y()) continue;
        const bool shellYZ = std::abs(dz) == r || std::abs(dy) == r;
        for (int dx = -r; dx <= r; dx += (shellYZ || r == 0) ? 1 : 2 * r) {
          const int x = centre.x() + dx;
          if (x < 0 || x >= dims_.x()) continue;
          // Skip a cell whose box is farther than the best hit so far.
          const Eigen::Vector3d lo = origin_ + cell_ * Eigen::Vector3d(x, y, z);
          const Eigen::Vector3d gap =
              (lo - p).cwiseMax(p - (lo.array() + cell_).matrix()).cwiseMax(0.0);
          if (gap.squaredNorm() > best * best) continue;
          const long key = cellKey(x, y, z);
          for (int i = cellStart_[static_cast<std::size_t>(key)];
               i < cellStart_[static_cast<std::size_t>(key) + 1]; ++i) {
            const int t = items_[static_cast<std::size_t>(i)];
            const auto& tri = mesh_.triangles[static_cast<std::size_t>(t)];
            const Eigen::Vector3d a = corner(mesh_, tri, 0), b = corner(mesh_, tri, 1),
                                  c = corner(mesh_, tri, 2);
            const Eigen::Vector3d q = closestPointOnTriangle(p, a, b, c);
            const double d = (q - p).norm();
            if (d <= best) {
              best = d;
              found = true;
              hit.point = q;
              hit.triangle = t;
              hit.distance = d;
            }
          }
        }
      }
    }
    if (found && best <= static_cast<double>(r) * cell_) break;
  }
  if (!found) return std::nullopt;
  const auto& tri = mesh_.triangles[static_cast<std::size_t>(hit.triangle)];
  hit.barycentric =
      barycentricOf(hit.point, corner(mesh_, tri, 0), corner(mesh_, tri, 1), corner(mesh_, tri, 2));
  hit.normal = normals_[static_cast<std::size_t>(hit.triangle)];
  return hit;
}

}  // namespace clm3d
