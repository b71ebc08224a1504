// The real scan renders: the james head from /work/shared/data (skipped without it).
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/mesh/mesh_import.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

TEST(JamesRender, FrontalRenderCoversTheFaceWithTexture) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const TexturedMesh mesh = loadTexturedMesh(data / "scans/james/james.obj");
  OffscreenRenderer renderer(mesh);
  const Eigen::Vector3f centre = mesh.bounds().center();
  Pose pose = Pose::fromDegrees(0, 0, 0, {0, 0, -900});
  pose.translation -= centre.cast<double>();
  const RenderResult result = renderer.render(pose, Camera::fromVerticalFov(256, 256, 30));
  std::vector<cv::Mat> channels;
  cv::split(result.bgra, channels);
  const double coverage = cv::countNonZero(channels[3]) / (256.0 * 256.0);
  EXPECT_GT(coverage, 0.15);
  EXPECT_LT(coverage, 0.9);
  // Corners are background; the centre is textured skin (not grey, not black).
  EXPECT_EQ(result.bgra.at<cv::Vec4b>(0, 0)[3], 0);
  EXPECT_EQ(result.bgra.at<cv::Vec4b>(255, 255)[3], 0);
  const cv::Vec4b centrePixel = result.bgra.at<cv::Vec4b>(128, 128);
  EXPECT_EQ(centrePixel[3], 255);
  EXPECT_GT(centrePixel[2], centrePixel[0]);  // skin: more red than blue
  const cv::Scalar mean = cv::mean(result.bgra, channels[3]);
  EXPECT_GT(mean[2], 60.0);
  // Finite depth exactly where alpha is set.
  cv::Mat finite = result.depth < 1e6F;
  EXPECT_EQ(cv::countNonZero(finite != channels[3]), 0);
  if (const char* out = std::getenv("CLM3D_TEST_SAVE_RENDERS"))
    cv::imwrite(std::string(out) + "/james-frontal.png", result.bgra);
}

}  // namespace
}  // namespace clm3d
