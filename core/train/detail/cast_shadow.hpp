// Cast shadows for training renders: the renderer lights each surface by its own normal only, so
// a nose lit from the side casts no shadow on the cheek. Here the face is also rendered from the
// light (a distant, narrow perspective camera along the light direction: nearly orthographic) and
// every pixel of the main render whose 3D point (from the main depth buffer) lies behind that
// light-view depth map is darkened to the ambient level (a second, ambient-only render).
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"
#include "core/render/offscreen_renderer.hpp"

namespace clm3d {

struct LightView {
  Pose pose;      // model to light-eye coordinates: the light looks at the centre along -direction
  Camera camera;  // distant and narrow, covering a sphere of the given radius
  Eigen::Vector3d directionEye{0.0, 0.0, 1.0};  // towards the light, main eye space, unit
  double pixelMm = 1.0;  // the side of a light-map pixel at the model, millimetres
};

// The view from the light (direction in the main render's eye space, towards the light) of a
// model posed by `modelPose`, centred on `centreModel` and covering `radiusMm` around it.
LightView lightView(const Pose& modelPose, const Eigen::Vector3d& lightDirectionEye,
                    const Eigen::Vector3d& centreModel, double radiusMm, int sizePixels);

// Per pixel of `view`, the share (0..1) of its 3x3 neighbourhood in the light's depth map that
// hides it from the light: 1 = fully in shadow. 0 on the background and where the point falls
// outside the light's view. A point counts as hidden when it is farther from the light than the
// map by more than a bias that grows with the surface's slope to the light (normal from the
// view's depth buffer), so that a surface does not shadow itself. CV_32F, the size of view.depth.
cv::Mat shadowMask(const RenderResult& view, const RenderResult& fromLight, const LightView& light);

// The render `lit` (made with `lighting`) with the shadows the mesh casts on itself: renders the
// light's depth map and an ambient-only image with `renderer` and blends them by shadowMask.
// Returns premultiplied BGRA like lit.bgra; alpha unchanged.
cv::Mat renderCastShadows(OffscreenRenderer& renderer, const RenderResult& lit,
                          const Lighting& lighting, const Eigen::Vector3d& centreModel,
                          double radiusMm);

}  // namespace clm3d
