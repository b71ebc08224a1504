// Meshes built in code for the renderer tests: flat textured squares at known places, so that
// coverage, colour and depth have analytic answers.
#pragma once

#include <opencv2/core.hpp>

#include "core/mesh/textured_mesh.hpp"

namespace clm3d::test {

// The four quadrant colours of quadrantTexture(), as seen in the image (BGR).
inline const cv::Vec3b kTopLeft{0, 0, 255};          // red
inline const cv::Vec3b kTopRight{0, 255, 0};         // green
inline const cv::Vec3b kBottomLeft{255, 0, 0};       // blue
inline const cv::Vec3b kBottomRight{255, 255, 255};  // white

// 64x64, one colour per quadrant (row 0 = top).
inline cv::Mat quadrantTexture() {
  cv::Mat texture(64, 64, CV_8UC3);
  texture(cv::Rect(0, 0, 32, 32)).setTo(cv::Scalar(kTopLeft[0], kTopLeft[1], kTopLeft[2]));
  texture(cv::Rect(32, 0, 32, 32)).setTo(cv::Scalar(kTopRight[0], kTopRight[1], kTopRight[2]));
  texture(cv::Rect(0, 32, 32, 32))
      .setTo(cv::Scalar(kBottomLeft[0], kBottomLeft[1], kBottomLeft[2]));
  texture(cv::Rect(32, 32, 32, 32))
      .setTo(cv::Scalar(kBottomRight[0], kBottomRight[1], kBottomRight[2]));
  return texture;
}

// Appends an axis-aligned square of half-size `half` in the plane z = `z`, centred on (cx, cy),
// facing +z, with UVs spanning [u0, u1] x [v0, v1].
inline void addSquare(TexturedMesh& mesh, float cx, float cy, float z, float half, float u0 = 0,
                      float v0 = 0, float u1 = 1, float v1 = 1) {
  const int base = static_cast<int>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {{cx - half, cy - half, z},
                                               {cx + half, cy - half, z},
                                               {cx + half, cy + half, z},
                                               {cx - half, cy + half, z}});
  mesh.uvs.insert(mesh.uvs.end(), {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}});
  mesh.triangles.insert(mesh.triangles.end(),
                        {{base, base + 1, base + 2}, {base, base + 2, base + 3}});
}

// A 100 mm square at z = 0 with the quadrant texture.
inline TexturedMesh texturedSquare(float half = 50.0F) {
  TexturedMesh mesh;
  addSquare(mesh, 0, 0, 0, half);
  mesh.texture = quadrantTexture();
  mesh.source = "texturedSquare";
  mesh.computeNormals();
  return mesh;
}

// A single-colour mesh of the given squares (centre x, centre y, z, half-size).
inline TexturedMesh whiteSquares(std::initializer_list<cv::Vec4f> squares) {
  TexturedMesh mesh;
  for (const auto& s : squares) addSquare(mesh, s[0], s[1], s[2], s[3], 0.5F, 0.5F, 0.5F, 0.5F);
  mesh.texture = cv::Mat(2, 2, CV_8UC3, cv::Scalar(255, 255, 255));
  mesh.source = "whiteSquares";
  mesh.computeNormals();
  return mesh;
}

}  // namespace clm3d::test
