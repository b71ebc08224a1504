// `clm3d render` end to end: exit codes (0 ok, 1 bad input, 2 bad usage), a PNG with a
// transparent background, landmark and depth outputs.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/mesh/mesh_export.hpp"
#include "core/scheme/landmark_file.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::quoted;

using test::runClm3d;
using test::TempDir;

// A 100 mm square facing +z, textured left red / right blue, saved as OBJ + MTL + PNG.
std::filesystem::path writeSquare(const TempDir& dir) {
  TexturedMesh mesh;
  mesh.positions = {{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}};
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.texture = cv::Mat(8, 8, CV_8UC3, cv::Scalar(0, 0, 255));
  mesh.texture(cv::Rect(4, 0, 4, 8)).setTo(cv::Scalar(255, 0, 0));
  mesh.source = "square";
  const auto path = dir / "square.obj";
  saveObj(mesh, path);
  return path;
}

TEST(RenderCli, WritesATransparentPng) {
  TempDir dir;
  const auto mesh = writeSquare(dir);
  const auto out = dir / "out.png";
  const auto depth = dir / "depth.tiff";
  const auto result = runClm3d("render --mesh " + quoted(mesh) + " --size 96 --out " + quoted(out) +
                               " --out-depth " + quoted(depth));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const cv::Mat image = cv::imread(out.string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(image.type(), CV_8UC4);
  ASSERT_EQ(image.size(), cv::Size(96, 96));
  EXPECT_EQ(image.at<cv::Vec4b>(0, 0)[3], 0);
  EXPECT_EQ(image.at<cv::Vec4b>(95, 95)[3], 0);
  EXPECT_EQ(image.at<cv::Vec4b>(48, 30)[3], 255);
  EXPECT_GT(image.at<cv::Vec4b>(48, 30)[2], 100);  // red on the left (subject's right)
  EXPECT_GT(image.at<cv::Vec4b>(48, 66)[0], 100);  // blue on the right
  const cv::Mat depthMap = cv::imread(depth.string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(depthMap.type(), CV_32F);
  EXPECT_EQ(depthMap.at<float>(0, 0), 0.0F);
  EXPECT_GT(depthMap.at<float>(48, 48), 10.0F);
}

TEST(RenderCli, ProjectsLandmarks) {
  TempDir dir;
  const auto mesh = writeSquare(dir);
  // 25 points on the square; point 1 (the centre of rotation) at its middle.
  LandmarkSet points(25, 3);
  for (int i = 0; i < 25; ++i)
    points.set(i, Eigen::Vector3d(-40.0 + 20.0 * (i % 5), 40.0 - 20.0 * (i / 5), 0.0));
  points.set(0, Eigen::Vector3d(0, 0, 0));
  points.set(7, Eigen::Vector3d(20, 10, 0));    // left eye centre (subject's left = +x)
  points.set(10, Eigen::Vector3d(-20, 10, 0));  // right eye centre
  points.set(24, Eigen::Vector3d(0, 0, -30));   // behind the square: hidden
  const auto landmarks = dir / "square.ljson";
  writeLandmarks(landmarks, points, Scheme::thesis25());
  const auto out2d = dir / "square.pts";
  const auto overlay = dir / "overlay.png";
  const auto result =
      runClm3d("render --mesh " + quoted(mesh) + " --landmarks " + quoted(landmarks) +
               " --yaw 20 --size 128 --out " + quoted(dir / "out.png") + " --out-landmarks " +
               quoted(out2d) + " --overlay " + quoted(overlay) + " --hidden-missing");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const LandmarkSet projected = readLandmarks(out2d, &Scheme::thesis25());
  EXPECT_EQ(projected.dims(), 2);
  EXPECT_EQ(projected.presentCount(), 24);
  EXPECT_FALSE(projected.has(24));
  EXPECT_GT(projected.point(0).x(), 40);
  EXPECT_LT(projected.point(0).x(), 88);
  // Yaw 20 turns the subject's left (+x) away from the camera: the left eye is nearer the centre.
  const double leftOffset = projected.point(7).x() - projected.point(0).x();
  const double rightOffset = projected.point(0).x() - projected.point(10).x();
  EXPECT_GT(leftOffset, 0);
  EXPECT_GT(rightOffset, 0);
  EXPECT_LT(leftOffset, rightOffset);
  EXPECT_NEAR(projected.point(7).y(), projected.point(10).y(), 1.0);
  EXPECT_TRUE(std::filesystem::exists(overlay));
}

TEST(RenderCli, RendersJamesTurned) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  TempDir dir;
  const auto out = dir / "james.png";
  const auto result = runClm3d("render --mesh " + quoted(data / "scans/james/james.obj") +
                               " --yaw 40 --out " + quoted(out));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const cv::Mat image = cv::imread(out.string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(image.type(), CV_8UC4);
  EXPECT_EQ(image.at<cv::Vec4b>(0, 0)[3], 0);
  EXPECT_EQ(image.at<cv::Vec4b>(0, 255)[3], 0);
  EXPECT_EQ(image.at<cv::Vec4b>(128, 128)[3], 255);
}

TEST(RenderCli, BrokenMeshIsBadInput) {
  TempDir dir;
  const auto broken = dir / "broken.obj";
  test::writeFile(broken, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  const auto result =
      runClm3d("render --mesh " + quoted(broken) + " --out " + quoted(dir / "x.png"));
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("broken.obj"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));

  const auto missing =
      runClm3d("render --mesh " + quoted(dir / "nothere.obj") + " --out " + quoted(dir / "x.png"));
  EXPECT_EQ(missing.exitCode, 1) << missing.output;
  EXPECT_NE(missing.output.find("nothere.obj"), std::string::npos) << missing.output;
}

TEST(RenderCli, BadUsageExitsWithTwo) {
  TempDir dir;
  const auto mesh = writeSquare(dir);
  EXPECT_EQ(runClm3d("render --mesh " + quoted(mesh)).exitCode, 2);  // no --out
  EXPECT_EQ(
      runClm3d("render --mesh " + quoted(mesh) + " --out " + quoted(dir / "x.png") + " --size -3")
          .exitCode,
      2);
  EXPECT_EQ(
      runClm3d("render --mesh " + quoted(mesh) + " --out " + quoted(dir / "x.png") + " --up +q")
          .exitCode,
      2);
  EXPECT_EQ(runClm3d("render --mesh " + quoted(mesh) + " --out " + quoted(dir / "x.png") +
                     " --light-dir 1,2")
                .exitCode,
            2);
}

}  // namespace
}  // namespace clm3d
