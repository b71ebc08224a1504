// The offscreen renderer: draws a TexturedMesh at a Pose through a Camera into a BGRA image
// (alpha = coverage, for the CLM's alpha masks) and an eye-depth buffer (for hidden landmarks).
// Geometry follows core/geometry exactly, so projectPoint lands on the rendered pixel.
// One renderer per thread; several renderers may draw at the same time on different threads.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <opencv2/core/mat.hpp>

#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"
#include "core/mesh/textured_mesh.hpp"

namespace clm3d {

// Ambient plus one directional light, both white. A surface of texture colour c and eye-space
// normal n is drawn as c * min(1, ambient + diffuse * max(0, n . l)), with l = direction
// normalised; surfaces seen from behind are lit with their normal flipped.
struct Lighting {
  Eigen::Vector3d direction{0.3, 0.4, 1.0};  // towards the light, eye space (+z = towards viewer)
  double ambient = 0.45;
  double diffuse = 0.65;
};

struct RenderResult {
  cv::Mat bgra;   // CV_8UC4, row 0 at the top; alpha 255 on the mesh, 0 on the background
  cv::Mat depth;  // CV_32F, eye distance in millimetres along -z; +inf on the background
  Pose pose;
  Camera camera;

  // True if the model point is in the image and not hidden behind the rendered surface: its eye
  // depth is at most toleranceMm behind the depth buffer at one of the 4 pixels around its
  // projection (projectPoint).
  bool isVisible(const Eigen::Vector3d& modelPoint, double toleranceMm = 2.0) const;
  // The depth buffer with the background at 0 instead of +inf (for saving as an image).
  cv::Mat depthZeroBackground() const;
};

struct RenderOptions {
  // Renders at supersample x the resolution and averages down (anti-aliased edges and alpha).
  // Depth takes the nearest surface of each block.
  int supersample = 1;
};

class OffscreenRenderer {
 public:
  // Uploads the mesh (computing normals if it has none). Throws InputError if the mesh is invalid
  // (TexturedMesh::validate), Error if the render module cannot be loaded or fails.
  explicit OffscreenRenderer(const TexturedMesh& mesh, const RenderOptions& options = {});
  ~OffscreenRenderer();
  OffscreenRenderer(OffscreenRenderer&&) noexcept;
  OffscreenRenderer& operator=(OffscreenRenderer&&) noexcept;
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  RenderResult render(const Pose& pose, const Camera& camera, const Lighting& lighting = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clm3d
