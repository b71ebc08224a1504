#include "core/render/view_tiles.hpp"

#include <algorithm>

#include "core/geometry/projection.hpp"
#include "core/render/framing.hpp"
#include "core/render/offscreen_renderer.hpp"

namespace clm3d {
namespace {

constexpr double kTileFovDeg = 20.0;
constexpr int kTileSupersample = 2;

}  // namespace

std::vector<ViewAngles> trainingViewAngles() {
  std::vector<ViewAngles> angles;
  for (const double pitch : {-30.0, 0.0, 30.0}) {
    for (const double yaw : {-60.0, -30.0, 0.0, 30.0, 60.0}) angles.push_back({pitch, yaw});
  }
  return angles;
}

std::vector<cv::Mat> renderTilesAboutPivot(const TexturedMesh& mesh,
                                           const std::vector<ViewAngles>& angles, int size,
                                           const Eigen::Vector3d& pivot, double radius) {
  if (radius <= 0.0) radius = meshRadius(mesh, pivot);
  OffscreenRenderer renderer(mesh, RenderOptions{kTileSupersample});
  std::vector<cv::Mat> tiles;
  for (const ViewAngles& view : angles) {
    Camera camera = Camera::fromVerticalFov(size, size, kTileFovDeg);
    Pose pose = Pose::fromDegrees(view.pitchDeg, view.yawDeg, 0.0);
    const double distance = -distanceToFit(radius, camera, 1.1);
    camera = Camera::fromVerticalFov(size, size, kTileFovDeg, distance - radius - 10.0,
                                     distance + radius + 10.0);
    pose.translation = Eigen::Vector3d(0.0, 0.0, -distance) - pose.rotation() * pivot;
    tiles.push_back(renderer.render(pose, camera).bgra);
  }
  return tiles;
}

std::vector<cv::Mat> renderTilesFramedOn(const TexturedMesh& mesh, const TexturedMesh& frameOn,
                                         const std::vector<ViewAngles>& angles, int size,
                                         double fill) {
  OffscreenRenderer renderer(mesh, RenderOptions{kTileSupersample});
  std::vector<cv::Mat> tiles;
  for (const ViewAngles& view : angles) {
    const Camera camera = Camera::fromVerticalFov(size, size, kTileFovDeg);
    Pose pose = Pose::fromDegrees(view.pitchDeg, view.yawDeg, 0.0);
    pose.translation = frameMesh(frameOn, pose, camera, fill);
    tiles.push_back(renderer.render(pose, camera).bgra);
  }
  return tiles;
}

}  // namespace clm3d
