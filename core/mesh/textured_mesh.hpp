// A triangle mesh with one texture image: what the importers produce, the renderer draws and the
// procedural head generator makes. Per-vertex attributes (an importer splits vertices where UVs
// or normals differ), so the arrays can go to OpenGL as they are.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

namespace clm3d {

struct TexturedMesh {
  std::vector<Eigen::Vector3f> positions;  // model units (millimetres for faces)
  std::vector<Eigen::Vector3f> normals;    // unit length, one per position (may be empty)
  std::vector<Eigen::Vector2f> uvs;        // one per position; (0, 0) = bottom-left of texture
  std::vector<Eigen::Vector3i> triangles;  // counter-clockwise seen from outside
  cv::Mat texture;                         // CV_8UC3, BGR (OpenCV order), row 0 = top
  std::string source;                      // file it came from, for messages

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return triangles.size(); }

  // Area-weighted vertex normals from the triangles.
  void computeNormals();
  // Axis-aligned bounds of the positions.
  Eigen::AlignedBox3f bounds() const;
  // Moves every position by `offset` (e.g. to put landmark 1 at the origin).
  void translate(const Eigen::Vector3f& offset);

  // Throws InputError naming `source` if the mesh cannot be rendered: no faces, indices out of
  // range, non-finite coordinates, UVs missing or of the wrong count, empty texture.
  void validate() const;
};

}  // namespace clm3d
