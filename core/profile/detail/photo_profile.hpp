// Photo profiling (as 3DDFA's 300W-LP was made): a dense morphable face (dense_face.hpp) fitted to
// a photo's 2D points (pose, identity and a few expressions, with their prior), textured from the
// photo by projection, and rendered turned to other yaws and pitches over the photo with the face
// region filled in from around it. The truth of a turned view is exact for the dense face: its
// landmarks projected through the same pose and camera as the render.
// Limits (docs/synthetic-sequences.md): the texture is the photo seen from its own pose, so a
// side the photo shows at a grazing angle is stretched and a side it does not show is the mirror
// image of the other; hair, ears beyond the model and the background do not turn; the photo's
// light turns with the face.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"
#include "core/mesh/textured_mesh.hpp"
#include "core/profile/dense_face.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/scheme/landmark_set.hpp"

namespace clm3d {

struct ProfileSettings {
  // Expected error of the photo's points, as a share of their box's larger side: weighs the
  // points against the modes' prior (smaller trusts the points more).
  double pointSigmaShare = 0.01;
  int maxIterations = 60;  // Levenberg-Marquardt iterations per starting yaw
  // The photo shows a vertex where it is visible there and its normal faces the camera at least
  // this much (cosine). Low: a side seen at a grazing angle is stretched but stays skin; at 0.3 a
  // frontal photo left the band between cheek and ear to the background's blur.
  double trustCosine = 0.05;
  double depthToleranceMm = 3.0;  // depth test of vertices and landmarks against the render
  // The photo's face region (the fitted face rendered at the photo's pose) grown by this share
  // of the face's size is filled from around it to make the background of turned views.
  double backgroundMarginShare = 0.04;
  int supersample = 2;  // renders at N times the size, averaged down

  void validate() const;  // InputError for values out of range
};

struct PhotoProfile {
  Camera camera;             // the photo's camera (its size)
  Pose pose;                 // the head's pose in the photo
  Eigen::VectorXd weights;   // per mode of the dense face
  Eigen::Matrix3Xd columns;  // the fitted dense face (model coordinates, mm)
  LandmarkSet landmarks;     // its scheme landmarks, 3D, model coordinates
  int pointsFitted = 0;      // present photo points with a landmark on the dense face
  double rmsPixels = 0.0;    // their fit residual
  // The fitted face; texture: the photo and the background side by side (left and right half).
  TexturedMesh mesh;
  cv::Mat background;            // the photo with the face region filled in (8-bit BGR)
  double mirroredShare = 0.0;    // share of the triangles textured from their mirror image
  double backgroundShare = 0.0;  // share of the triangles wearing the background
};

// Fits `face` to `points` (2D, the face's scheme order; missing points ignored) seen through
// `camera`: pose, then the modes' weights with their N(0, 1) prior. Fills camera, pose, weights,
// columns, landmarks, pointsFitted and rmsPixels. Throws InputError for fewer than 4 points with a
// landmark on the face or a wrong point count.
PhotoProfile fitPhotoProfile(const DenseFace& face, const LandmarkSet& points, const Camera& camera,
                             const ProfileSettings& settings = {});

// Textures the fitted face from `photo` (8-bit BGR of the camera's size) and makes the
// background: fills mesh, background, mirroredShare and backgroundShare.
void texturePhotoProfile(const DenseFace& face, const cv::Mat& photo, PhotoProfile& profile,
                         const ProfileSettings& settings = {});

// fitPhotoProfile then texturePhotoProfile.
PhotoProfile profilePhoto(const DenseFace& face, const cv::Mat& photo, const LandmarkSet& points,
                          const Camera& camera, const ProfileSettings& settings = {});

// The pixels of `image` (8-bit, 1 or 3 channels) where `mask` is non-zero, filled smoothly from
// the others (a push-pull pyramid: masked averages going down, blended back coming up).
cv::Mat fillMaskedRegion(const cv::Mat& image, const cv::Mat& mask);

// One turned view of a profile.
struct ProfiledView {
  Pose pose;
  cv::Mat bgr;                // the turned face over the background
  cv::Mat alpha;              // CV_8U coverage of the face
  Eigen::Matrix2Xd points;    // the landmarks projected (NaN columns where missing)
  std::vector<bool> visible;  // present, in the image and not hidden behind the face
};

// Renders a profile at other head angles: the photo's pose with pitch and yaw replaced (roll,
// place and size kept; the head turns about landmark 1). The light leaves the texture as it is.
// Keeps a copy of the profile's mesh, background and landmarks: the profile need not stay alive.
class ProfileRenderer {
 public:
  ProfileRenderer(const PhotoProfile& profile, const ProfileSettings& settings = {});
  ~ProfileRenderer();
  ProfileRenderer(ProfileRenderer&&) noexcept;
  ProfileRenderer& operator=(ProfileRenderer&&) noexcept;

  ProfiledView render(double pitchDeg, double yawDeg);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clm3d
