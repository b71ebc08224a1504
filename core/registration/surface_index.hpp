// A uniform grid over a mesh's triangles for nearest-surface-point queries within a search
// radius: what non-rigid ICP (one query per template vertex per iteration) and texture baking (one
// query per texel) need many times per second, where mesh_distance's brute force is too slow.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/mesh/textured_mesh.hpp"

namespace clm3d {

struct SurfaceHit {
  Eigen::Vector3d point;        // nearest surface point
  Eigen::Vector3d barycentric;  // of `point` in the triangle (weights of its three corners)
  Eigen::Vector3d normal;       // unit geometric normal of the triangle (counter-clockwise side)
  double distance = 0.0;
  int triangle = -1;
};

class SurfaceIndex {
 public:
  // Indexes the mesh's triangles (the mesh must outlive the index). Cells are about twice the
  // mean edge length. Degenerate triangles are skipped.
  explicit SurfaceIndex(const TexturedMesh& mesh);

  // The nearest surface point within maxDistance of p, or nullopt when there is none.
  std::optional<SurfaceHit> nearest(const Eigen::Vector3d& p, double maxDistance) const;

  const TexturedMesh& mesh() const { return mesh_; }

 private:
  long cellKey(long x, long y, long z) const;
  Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const;

  const TexturedMesh& mesh_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  Eigen::Vector3i dims_ = Eigen::Vector3i::Ones();
  double cell_ = 1.0;
  std::vector<int> cellStart_;  // CSR: triangles of cell c are items_[cellStart_[c] .. [c + 1])
  std::vector<int> items_;
  std::vector<Eigen::Vector3d> normals_;  // per triangle
};

}  // namespace clm3d
