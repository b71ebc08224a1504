// Baking a target mesh's texture into a registered template's UV layout: every texel covered by
// a template triangle in UV space is a 3D point on the registered template; the nearest target
// surface point (within a distance, facing the same way) gives the colour, read bilinearly from
// the target texture at its UV. Texels with no target surface (back of the head missing in a scan)
// and the texels around the UV islands are filled from their neighbours (push-pull), so neither
// holes nor seams show when the template is rendered.
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/common/progress.hpp"
#include "core/mesh/textured_mesh.hpp"

namespace clm3d {

struct TextureBakeOptions {
  int width = 1024, height = 1024;  // of the baked texture
  double maxDistance = 8.0;         // mm from the template point to the target surface
  double minNormalDot = 0.0;        // cosine between template and target normals
  // Per template triangle, whether it takes colour from the target (empty = all); the others are
  // filled from their neighbours in UV space like uncovered texels.
  std::vector<bool> bakeTriangles;
};

struct TextureBakeResult {
  cv::Mat texture;  // CV_8UC3 BGR, row 0 = top, UV (0, 0) at the bottom-left
  cv::Mat
      coverage;  // CV_8U: 255 baked from the target, 128 inside a triangle but filled, 0 outside
  double bakedFraction = 0.0;  // baked texels / texels inside template triangles
};

// `templ` gives the triangles and UVs, `positions` the registered position of each of its
// vertices (same frame as `target`). Throws InputError for an empty template or target, a
// position count that does not match, a target without texture or UVs, or a size out of
// [8, 8192]; Cancelled.
TextureBakeResult bakeTexture(const TexturedMesh& templ,
                              const std::vector<Eigen::Vector3f>& positions,
                              const TexturedMesh& target, const TextureBakeOptions& options = {},
                              const ProgressCallback& progress = {},
                              const CancelToken* cancel = nullptr);

// Fills the texels of `image` (CV_8UC3) where `known` (CV_8U) is zero from the known ones by
// push-pull: averaging down an image pyramid and interpolating back up, so a hole gets a smooth
// blend of the colours around it. Throws InputError if no texel is known.
void fillUnknownTexels(cv::Mat& image, const cv::Mat& known);

}  // namespace clm3d
