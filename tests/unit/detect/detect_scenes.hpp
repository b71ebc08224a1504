// Test scenes for the detector and initialisation tests: a textured head (procedural or a scan)
// rendered at a known pose into a 640x480 frame over a smooth random background, with the exact
// projected landmarks, so a detector box can be compared with the truth.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"
#include "core/geometry/projection.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/scheme/landmark_set.hpp"

namespace clm3d::test {

// The camera of every scene: 640x480, 45 degrees vertical field of view (a webcam).
inline Camera sceneCamera() {
  return Camera::fromVerticalFov(640, 480, 45.0, 10.0, 10000.0);
}

struct Scene {
  cv::Mat bgr;              // CV_8UC3
  Pose pose;                // model (landmark coordinates) to eye
  Eigen::Matrix2Xd truth;   // every landmark, pixels
  Eigen::Vector2d eyeMid;   // midpoint of the projected eye centres (landmarks 8 and 11)
  double iodPixels = 0.0;   // projected distance between the eye centres
  double iodFrontal = 0.0;  // the same face's eye distance if it were frontal at its depth
};

// A smooth random grey background (low-frequency noise, levels about 50..200).
inline cv::Mat sceneBackground(int width, int height, std::uint64_t seed) {
  cv::Mat coarse(height / 40 + 2, width / 40 + 2, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(coarse, cv::RNG::UNIFORM, 50, 200);
  cv::Mat smooth;
  cv::resize(coarse, smooth, cv::Size(width, height), 0, 0, cv::INTER_CUBIC);
  cv::GaussianBlur(smooth, smooth, cv::Size(0, 0), 12.0);
  cv::Mat bgr;
  cv::cvtColor(smooth, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

// Renders `renderer`'s mesh with the landmark set's point 1 (index 0) at `centre` (pixels), the
// given angles (degrees) and eye distance in pixels when frontal. `landmarks` are in the mesh's
// coordinates; the rotation is about landmark 1. eyes: the eye-centre indices.
inline Scene renderScene(OffscreenRenderer& renderer, const LandmarkSet& landmarks,
                         const Camera& camera, double pitchDeg, double yawDeg, double rollDeg,
                         const Eigen::Vector2d& centre, double iodFrontalPixels,
                         std::uint64_t backgroundSeed, int eyeLeft = 7, int eyeRight = 10) {
  const Eigen::Vector3d origin = landmarks.point(0);
  const double iod3d = (landmarks.point(eyeLeft) - landmarks.point(eyeRight)).norm();
  const double depth = camera.focalX() * iod3d / iodFrontalPixels;
  Pose pose = Pose::fromDegrees(pitchDeg, yawDeg, rollDeg);
  pose.translation = camera.pixelToEye(centre, depth) - pose.rotation() * origin;

  Scene scene;
  scene.pose = pose;
  const RenderResult result = renderer.render(pose, camera);
  scene.bgr = sceneBackground(camera.width, camera.height, backgroundSeed);
  for (int r = 0; r < camera.height; ++r) {
    for (int c = 0; c < camera.width; ++c) {
      const cv::Vec4b p = result.bgra.at<cv::Vec4b>(r, c);
      cv::Vec3b& out = scene.bgr.at<cv::Vec3b>(r, c);
      const double a = p[3] / 255.0;
      for (int k = 0; k < 3; ++k) {
        out[k] = cv::saturate_cast<unsigned char>(a * p[k] + (1.0 - a) * out[k]);
      }
    }
  }
  scene.truth = projectPoints(landmarks.matrix(), pose, camera);
  const Eigen::Vector2d left = scene.truth.col(eyeLeft);
  const Eigen::Vector2d right = scene.truth.col(eyeRight);
  scene.eyeMid = 0.5 * (left + right);
  scene.iodPixels = (left - right).norm();
  const Eigen::Vector3d mid3 =
      pose.toEye(Eigen::Vector3d(0.5 * (landmarks.point(eyeLeft) + landmarks.point(eyeRight))));
  scene.iodFrontal = camera.focalX() * pose.scale * iod3d / -mid3.z();
  return scene;
}

}  // namespace clm3d::test
