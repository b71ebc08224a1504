// Procedural heads through the offscreen renderer, as the texture models will see them: a
// frontal 256x256 render with about 80 pixels between the eye centres. Every landmark but the
// earlobes must be visible, and the 20x20 patch around it must carry structure of its own.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "core/geometry/projection.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/scheme/scheme.hpp"
#include "core/synth/synth_head.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

constexpr int kPatch = 20;
constexpr double kInterOcularPixels = 80.0;

struct FrontalRender {
  SynthHead head;
  Pose pose;
  Camera camera;
  RenderResult result;
  cv::Mat grey;  // CV_64F
};

FrontalRender renderFrontal(std::uint64_t seed, const std::string& expression, double yaw = 0.0,
                            double pitch = 0.0) {
  FrontalRender r;
  SynthOptions options;
  options.textureSize = 1024;
  r.head = generateHead(seed, Expression::preset(expression), options);
  r.camera = Camera::fromVerticalFov(256, 256, 20.0, 100.0, 2000.0);
  const double iod = (r.head.landmarks.point(7) - r.head.landmarks.point(10)).norm();
  const double distance = r.camera.focalX() * iod / kInterOcularPixels;
  r.pose = Pose::fromDegrees(pitch, yaw, 0.0, {0.0, 50.0, -distance});
  OffscreenRenderer renderer(r.head.mesh);
  r.result = renderer.render(r.pose, r.camera);
  cv::Mat bgr;
  cv::cvtColor(r.result.bgra, bgr, cv::COLOR_BGRA2GRAY);
  bgr.convertTo(r.grey, CV_64F);
  return r;
}

cv::Mat patchAt(const FrontalRender& r, int landmark) {
  const Eigen::Vector2d p = projectPoint(r.head.landmarks.point(landmark), r.pose, r.camera);
  const cv::Rect box(static_cast<int>(std::lround(p.x())) - kPatch / 2,
                     static_cast<int>(std::lround(p.y())) - kPatch / 2, kPatch, kPatch);
  if ((box & cv::Rect(0, 0, r.grey.cols, r.grey.rows)) != box) return {};
  return r.grey(box).clone();
}

double ncc(const cv::Mat& a, const cv::Mat& b) {
  cv::Scalar ma, sa, mb, sb;
  cv::meanStdDev(a, ma, sa);
  cv::meanStdDev(b, mb, sb);
  const double cov = cv::mean((a - ma[0]).mul(b - mb[0]))[0];
  return cov / (sa[0] * sb[0]);
}

bool isEarlobe(int i) {
  return i == 18 || i == 24;
}

TEST(SynthRender, FrontalLandmarksAreVisibleAndOnTheFace) {
  for (const char* expression : {"neutral", "open-mouth", "smile"}) {
    const FrontalRender r = renderFrontal(21, expression);
    const double iod = (projectPoint(r.head.landmarks.point(7), r.pose, r.camera) -
                        projectPoint(r.head.landmarks.point(10), r.pose, r.camera))
                           .norm();
    EXPECT_NEAR(iod, kInterOcularPixels, 4.0);
    for (int i = 0; i < 25; ++i) {
      if (isEarlobe(i)) continue;
      const Eigen::Vector3d p = r.head.landmarks.point(i);
      EXPECT_TRUE(r.result.isVisible(p, 1.0))
          << expression << ": landmark " << i + 1 << " (" << Scheme::thesis25().id(i)
          << ") is hidden in the frontal view";
      const Eigen::Vector2d px = projectPoint(p, r.pose, r.camera);
      const int x = static_cast<int>(std::lround(px.x()));
      const int y = static_cast<int>(std::lround(px.y()));
      EXPECT_EQ(r.result.bgra.at<cv::Vec4b>(y, x)[3], 255)
          << expression << ": landmark " << i + 1 << " is not on the rendered face";
    }
  }
}

TEST(SynthRender, EarlobesAreVisibleInProfile) {
  SynthOptions options;
  options.textureSize = 256;
  const SynthHead head = generateHead(21, {}, options);
  OffscreenRenderer renderer(head.mesh);
  const Camera camera = Camera::fromVerticalFov(256, 256, 20.0, 100.0, 2000.0);
  // Negative yaw turns the nose to the subject's right and shows the left ear.
  for (const auto& [yaw, shown, hidden] : {std::tuple{-80.0, 18, 24}, std::tuple{80.0, 24, 18}}) {
    Pose pose = Pose::fromDegrees(0.0, yaw, 0.0);
    pose.translation =
        Eigen::Vector3d(0.0, 0.0, -600.0) - pose.rotation() * head.landmarks.point(shown);
    const RenderResult result = renderer.render(pose, camera);
    EXPECT_TRUE(result.isVisible(head.landmarks.point(shown), 1.0)) << "yaw " << yaw;
    EXPECT_FALSE(result.isVisible(head.landmarks.point(hidden), 1.0)) << "yaw " << yaw;
  }
}

TEST(SynthRender, LandmarkPatchesHaveDistinctStructure) {
  for (std::uint64_t seed : {21, 22, 23}) {
    const FrontalRender r = renderFrontal(seed, "neutral");
    std::vector<cv::Mat> patches(25);
    for (int i = 0; i < 25; ++i) {
      if (isEarlobe(i)) continue;
      patches[static_cast<std::size_t>(i)] = patchAt(r, i);
      ASSERT_FALSE(patches[static_cast<std::size_t>(i)].empty()) << "landmark " << i + 1;
      cv::Scalar mean, sd;
      cv::meanStdDev(patches[static_cast<std::size_t>(i)], mean, sd);
      // NCC matching ignores brightness scale, so contrast is relative to the patch's mean
      // (dark skin gives proportionally smaller grey-level spreads).
      EXPECT_GT(sd[0], 0.06 * mean[0]) << "seed " << seed << ": the patch of landmark " << i + 1
                                       << " (" << Scheme::thesis25().id(i) << ") is nearly flat";
      EXPECT_GT(sd[0], 3.0) << "seed " << seed << ": landmark " << i + 1;
    }
    for (int i = 0; i < 25; ++i) {
      for (int j = i + 1; j < 25; ++j) {
        if (isEarlobe(i) || isEarlobe(j)) continue;
        const double c =
            ncc(patches[static_cast<std::size_t>(i)], patches[static_cast<std::size_t>(j)]);
        EXPECT_LT(c, 0.9) << "seed " << seed << ": patches of landmarks " << i + 1 << " and "
                          << j + 1 << " are nearly the same";
      }
    }
  }
}

}  // namespace
}  // namespace clm3d
