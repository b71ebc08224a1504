// The pinhole camera of the thesis's appendix A.1.2: a symmetric OpenGL perspective frustum
// (eq. A.10-A.12) plus the viewport that maps normalised device coordinates to pixels.
// Pixel convention (as OpenCV): x right, y down, integer coordinates at pixel centres, so pixel
// (0, 0) covers [-0.5, 0.5)^2. On disk, .pts files add 1 (iBUG convention); in memory it is
// 0-based.
#pragma once

#include <Eigen/Core>

namespace clm3d {

// The vertical field of view assumed for video when none is given: a typical webcam's. Synthetic
// test sequences are rendered with it and the tracker assumes it, so both see the same camera.
inline constexpr double kDefaultVerticalFovDeg = 40.0;
// The vertical field of view assumed for a still image when none is given. A photo handed to
// clm3d is mostly a crop around the face (AFLW's are 120x120 pixels with the face filling them),
// taken from further away than a camera whose full frame is that crop would have to be: with 40
// degrees a face filling the image sits 0.3 m from the camera, and the model's ear lobes, 0.1 m
// behind the eyes, project 15% too far in. 20 degrees was chosen on AFLW training faces (430)
// and 100 LFPW training photos against 5, 10 and 40 (docs/fitting.md#the-camera-of-a-still-image).
inline constexpr double kStillImageVerticalFovDeg = 20.0;

struct Camera {
  int width = 256;
  int height = 256;
  double near = 10.0;    // millimetres, > 0
  double far = 10000.0;  // millimetres, > near
  double right = 1.0;    // frustum half-width at the near plane (r = -l)
  double top = 1.0;      // frustum half-height at the near plane (t = -b)

  // Square pixels: the half-height follows from the vertical field of view, the half-width
  // from the aspect ratio.
  static Camera fromVerticalFov(int width, int height, double verticalFovDegrees,
                                double near = 10.0, double far = 10000.0);

  // Focal length in pixels (horizontal and vertical are equal for cameras made above).
  double focalX() const;
  double focalY() const;

  // The OpenGL projection matrix of eq. A.10 (symmetric frustum).
  Eigen::Matrix4d projectionMatrix() const;

  // Eye coordinates to pixel coordinates (eq. A.12 followed by the viewport). Points must be in
  // front of the camera (z < 0).
  Eigen::Vector2d eyeToPixel(const Eigen::Vector3d& eye) const;
  // Inverse of eyeToPixel for a given eye-space depth (distance along -z, > 0).
  Eigen::Vector3d pixelToEye(const Eigen::Vector2d& pixel, double depth) const;
};

}  // namespace clm3d
