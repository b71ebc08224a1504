#include "core/train/detail/cast_shadow.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"

namespace clm3d {

LightView lightView(const Pose& modelPose, const Eigen::Vector3d& lightDirectionEye,
                    const Eigen::Vector3d& centreModel, double radiusMm, int sizePixels) {
  if (!(lightDirectionEye.norm() > 0.0)) throw Error("cast shadows: the light has no direction");
  // The light in model coordinates; the light camera's +z (towards its viewer) must be it. With
  // R = Rx(pitch) Ry(yaw) the third row of R is (-cos p sin y, sin p, cos p cos y).
  const Eigen::Vector3d l = modelPose.rotation().transpose() * lightDirectionEye.normalized();
  LightView light;
  light.pose.scale = modelPose.scale;
  light.pose.pitch = std::asin(std::clamp(l.y(), -1.0, 1.0));
  light.pose.yaw = std::atan2(-l.x(), l.z());
  light.pose.roll = 0.0;
  const double distance = 20.0 * radiusMm * modelPose.scale;
  light.pose.translation = Eigen::Vector3d(0.0, 0.0, -distance) -
                           modelPose.scale * (light.pose.rotation() * centreModel);
  const double reach = radiusMm * modelPose.scale;
  light.directionEye = lightDirectionEye.normalized();
  light.pixelMm = 2.0 * reach / sizePixels;
  const double fovDeg = 2.0 * std::atan(reach / distance) * 180.0 / 3.14159265358979323846;
  light.camera = Camera::fromVerticalFov(sizePixels, sizePixels, fovDeg, distance - 4.0 * reach,
                                         distance + 4.0 * reach);
  return light;
}

namespace {

// The eye-space point of a depth-buffer pixel, or nothing on the background.
bool eyePoint(const RenderResult& view, int x, int y, Eigen::Vector3d& out) {
  if (x < 0 || y < 0 || x >= view.depth.cols || y >= view.depth.rows) return false;
  const float depth = view.depth.at<float>(y, x);
  if (!std::isfinite(depth)) return false;
  out = view.camera.pixelToEye({x, y}, depth);
  return true;
}

// Tangent of the angle between the surface at pixel (x, y) (normal from the depth buffer) and
// the light direction, capped; the cap where the neighbours are missing.
double slopeToLight(const RenderResult& view, int x, int y, const Eigen::Vector3d& point,
                    const Eigen::Vector3d& light) {
  constexpr double kMaxTangent = 6.0;
  Eigen::Vector3d dx, dy, neighbour;
  if (eyePoint(view, x + 1, y, neighbour)) {
    dx = neighbour - point;
  } else if (eyePoint(view, x - 1, y, neighbour)) {
    dx = point - neighbour;
  } else {
    return kMaxTangent;
  }
  if (eyePoint(view, x, y + 1, neighbour)) {
    dy = neighbour - point;
  } else if (eyePoint(view, x, y - 1, neighbour)) {
    dy = point - neighbour;
  } else {
    return kMaxTangent;
  }
  const Eigen::Vector3d normal = dx.cross(dy);
  if (!(normal.norm() > 0.0)) return kMaxTangent;
  const double cosine = std::abs(normal.normalized().dot(light));
  const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
  return std::min(kMaxTangent, sine / std::max(cosine, 1e-6));
}

}  // namespace

cv::Mat shadowMask(const RenderResult& view, const RenderResult& fromLight,
                   const LightView& light) {
  cv::Mat mask(view.depth.size(), CV_32F, cv::Scalar(0));
  const Eigen::Matrix3d toModel = view.pose.rotation().transpose() / view.pose.scale;
  const cv::Mat& lightDepth = fromLight.depth;
  for (int y = 0; y < view.depth.rows; ++y) {
    float* out = mask.ptr<float>(y);
    for (int x = 0; x < view.depth.cols; ++x) {
      Eigen::Vector3d eye;
      if (!eyePoint(view, x, y, eye)) continue;
      const Eigen::Vector3d model = toModel * (eye - view.pose.translation);
      const Eigen::Vector3d lightEye = light.pose.toEye(model);
      if (lightEye.z() >= 0.0) continue;
      const Eigen::Vector2d at = light.camera.eyeToPixel(lightEye);
      const int cx = static_cast<int>(std::lround(at.x()));
      const int cy = static_cast<int>(std::lround(at.y()));
      // The 3x3 look-ups lie up to 1.5 light pixels from the point (rounding included); a
      // surface sloping away from the light by tan t changes depth by tan t per pixel of run.
      const double bias =
          1.0 + 2.0 * light.pixelMm * (0.5 + slopeToLight(view, x, y, eye, light.directionEye));
      const double distance = -lightEye.z();
      int hidden = 0;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int lx = cx + dx, ly = cy + dy;
          if (lx < 0 || ly < 0 || lx >= lightDepth.cols || ly >= lightDepth.rows) continue;
          const float occluder = lightDepth.at<float>(ly, lx);
          if (std::isfinite(occluder) && distance > occluder + bias) ++hidden;
        }
      }
      out[x] = static_cast<float>(hidden) / 9.0F;
    }
  }
  return mask;
}

cv::Mat renderCastShadows(OffscreenRenderer& renderer, const RenderResult& lit,
                          const Lighting& lighting, const Eigen::Vector3d& centreModel,
                          double radiusMm) {
  const int size = std::max(lit.bgra.cols, lit.bgra.rows);
  const LightView light = lightView(lit.pose, lighting.direction, centreModel, radiusMm, size);
  const RenderResult fromLight = renderer.render(light.pose, light.camera, lighting);
  cv::Mat mask = shadowMask(lit, fromLight, light);
  cv::GaussianBlur(mask, mask, cv::Size(0, 0), 0.8);  // a penumbra, not a jagged edge
  mask.setTo(0, lit.depth == std::numeric_limits<float>::infinity());
  Lighting ambientOnly = lighting;
  ambientOnly.diffuse = 0.0;
  const RenderResult dark = renderer.render(lit.pose, lit.camera, ambientOnly);
  cv::Mat out = lit.bgra.clone();
  for (int y = 0; y < out.rows; ++y) {
    const float* m = mask.ptr<float>(y);
    const auto* d = dark.bgra.ptr<cv::Vec4b>(y);
    auto* o = out.ptr<cv::Vec4b>(y);
    for (int x = 0; x < out.cols; ++x) {
      if (m[x] <= 0.0F) continue;
      for (int c = 0; c < 3; ++c) {
        o[x][c] = cv::saturate_cast<uchar>(o[x][c] + m[x] * (d[x][c] - o[x][c]));
      }
    }
  }
  return out;
}

}  // namespace clm3d
