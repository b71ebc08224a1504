// The renderer against analytic answers: coverage, texture orientation, depth, agreement with
// projectPoint, visibility, lighting, threads, and the module's symbol isolation.
#include "core/render/offscreen_renderer.hpp"

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <thread>
#include <vector>

#include "core/common/error.hpp"
#include "core/geometry/projection.hpp"
#include "core/render/detail/render_module.hpp"
#include "tests/support/test_support.hpp"
#include "tests/unit/render/render_test_meshes.hpp"

namespace clm3d {
namespace {

using test::texturedSquare;
using test::whiteSquares;

const Lighting kFlat{{0.0, 0.0, 1.0}, 1.0, 0.0};  // colour = texture exactly

Camera testCamera(int size = 200) {
  return Camera::fromVerticalFov(size, size, 30.0);
}

cv::Vec3b bgrAt(const cv::Mat& bgra, const Eigen::Vector2d& pixel) {
  const cv::Vec4b v = bgra.at<cv::Vec4b>(static_cast<int>(std::lround(pixel.y())),
                                         static_cast<int>(std::lround(pixel.x())));
  return {v[0], v[1], v[2]};
}

// Alpha-weighted centroid of the coverage inside a window.
Eigen::Vector2d coverageCentroid(const cv::Mat& bgra, const cv::Rect& window) {
  double sx = 0.0;
  double sy = 0.0;
  double sum = 0.0;
  for (int y = window.y; y < window.y + window.height; ++y) {
    for (int x = window.x; x < window.x + window.width; ++x) {
      const double a = bgra.at<cv::Vec4b>(y, x)[3];
      sx += a * x;
      sy += a * y;
      sum += a;
    }
  }
  return {sx / sum, sy / sum};
}

TEST(OffscreenRenderer, CoverageMatchesProjectedSquare) {
  OffscreenRenderer renderer(texturedSquare());
  const Camera camera = testCamera();
  const Pose pose = Pose::fromDegrees(0, 0, 0, {0, 0, -500});
  const RenderResult result = renderer.render(pose, camera, kFlat);
  ASSERT_EQ(result.bgra.type(), CV_8UC4);
  ASSERT_EQ(result.bgra.size(), cv::Size(200, 200));
  ASSERT_EQ(result.depth.type(), CV_32F);

  const Eigen::Vector2d lo = projectPoint({-50, 50, 0}, pose, camera);  // top-left corner
  const Eigen::Vector2d hi = projectPoint({50, -50, 0}, pose, camera);
  int covered = 0;
  for (int y = 0; y < 200; ++y) {
    for (int x = 0; x < 200; ++x) {
      const uchar alpha = result.bgra.at<cv::Vec4b>(y, x)[3];
      EXPECT_TRUE(alpha == 0 || alpha == 255);
      covered += alpha == 255;
      // Pixel centres clearly inside / outside the projected square.
      if (x > lo.x() + 1 && x < hi.x() - 1 && y > lo.y() + 1 && y < hi.y() - 1) {
        EXPECT_EQ(alpha, 255) << x << "," << y;
      }
      if (x < lo.x() - 1 || x > hi.x() + 1 || y < lo.y() - 1 || y > hi.y() + 1) {
        EXPECT_EQ(alpha, 0) << x << "," << y;
      }
    }
  }
  const double area = (hi.x() - lo.x()) * (hi.y() - lo.y());
  EXPECT_NEAR(covered, area, 2.0 * (hi.x() - lo.x()));
}

TEST(OffscreenRenderer, TextureIsTheRightWayUp) {
  OffscreenRenderer renderer(texturedSquare());
  const Camera camera = testCamera();
  const Pose pose = Pose::fromDegrees(0, 0, 0, {0, 0, -500});
  const RenderResult result = renderer.render(pose, camera, kFlat);
  // +y is up in the model, the image's top row is row 0; +x (subject's left) is image right.
  const auto expectColour = [&](const Eigen::Vector3d& model, const cv::Vec3b& colour) {
    const cv::Vec3b got = bgrAt(result.bgra, projectPoint(model, pose, camera));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], colour[c], 2) << model.transpose();
  };
  expectColour({-25, 25, 0}, test::kTopLeft);
  expectColour({25, 25, 0}, test::kTopRight);
  expectColour({-25, -25, 0}, test::kBottomLeft);
  expectColour({25, -25, 0}, test::kBottomRight);
}

TEST(OffscreenRenderer, DepthIsTheEyeDistanceOfTheSurface) {
  OffscreenRenderer renderer(texturedSquare());
  const Camera camera = testCamera();
  const Pose pose = Pose::fromDegrees(35, -20, 10, {5, -8, -480});
  const RenderResult result = renderer.render(pose, camera, kFlat);
  // The plane of the square in eye space: normal R * z, through the translation.
  const Eigen::Vector3d normal = pose.rotation() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d origin = pose.translation;
  int checked = 0;
  for (int y = 0; y < 200; y += 5) {
    for (int x = 0; x < 200; x += 5) {
      const float depth = result.depth.at<float>(y, x);
      if (result.bgra.at<cv::Vec4b>(y, x)[3] == 0) {
        EXPECT_TRUE(std::isinf(depth));
        continue;
      }
      const Eigen::Vector3d ray = camera.pixelToEye({x, y}, 1.0);  // at eye depth 1
      const double t = normal.dot(origin) / normal.dot(ray);       // eye depth of the hit
      EXPECT_NEAR(depth, t, 0.05) << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(OffscreenRenderer, ProjectPointLandsOnTheRenderedMarker) {
  const Eigen::Vector3d marker(31.0, -17.0, 12.0);
  for (const int supersample : {1, 3}) {
    OffscreenRenderer renderer(
        whiteSquares({{static_cast<float>(marker.x()), static_cast<float>(marker.y()),
                       static_cast<float>(marker.z()), 8.0F}}),
        RenderOptions{supersample});
    const Camera camera = testCamera(240);
    for (const Pose& pose :
         {Pose::fromDegrees(0, 0, 0, {0, 0, -400}), Pose::fromDegrees(-12, 25, 7, {-10, 6, -350}),
          Pose::fromDegrees(20, -30, -15, {4, 2, -300}, 1.2)}) {
      const RenderResult result = renderer.render(pose, camera);
      const Eigen::Vector2d expected = projectPoint(marker, pose, camera);
      const cv::Rect window(static_cast<int>(expected.x()) - 25,
                            static_cast<int>(expected.y()) - 25, 50, 50);
      const Eigen::Vector2d centroid = coverageCentroid(result.bgra, window);
      EXPECT_NEAR(centroid.x(), expected.x(), 0.5) << "supersample " << supersample;
      EXPECT_NEAR(centroid.y(), expected.y(), 0.5) << "supersample " << supersample;
    }
  }
}

TEST(OffscreenRenderer, PointsBehindASurfaceAreHidden) {
  // A small square 30 mm in front of a large one.
  OffscreenRenderer renderer(whiteSquares({{0, 0, 0, 60}, {0, 0, 30, 15}}));
  const Camera camera = testCamera();
  for (const Pose& pose :
       {Pose::fromDegrees(0, 0, 0, {0, 0, -500}), Pose::fromDegrees(10, 20, 0, {0, 0, -500})}) {
    const RenderResult result = renderer.render(pose, camera);
    EXPECT_FALSE(result.isVisible({0, 0, 0}));  // behind the small square
    EXPECT_FALSE(result.isVisible({5, -5, 0}));
    EXPECT_TRUE(result.isVisible({0, 0, 30}));   // on the small square
    EXPECT_TRUE(result.isVisible({45, 45, 0}));  // on the large one, in the open
    EXPECT_TRUE(result.isVisible({-50, 40, 0}));
    EXPECT_FALSE(result.isVisible({0, 0, -20}));  // inside/behind everything
  }
  // Outside the image.
  const RenderResult result = renderer.render(Pose::fromDegrees(0, 0, 0, {0, 0, -500}), camera);
  EXPECT_FALSE(result.isVisible({1000, 0, 0}));
}

TEST(OffscreenRenderer, LightDirectionChangesShading) {
  OffscreenRenderer renderer(whiteSquares({{0, 0, 0, 50}}));
  const Camera camera = testCamera();
  const Pose pose = Pose::fromDegrees(0, 0, 0, {0, 0, -500});
  const auto centreGrey = [&](const Lighting& lighting) {
    const RenderResult result = renderer.render(pose, camera, lighting);
    const cv::Vec4b v = result.bgra.at<cv::Vec4b>(100, 100);
    EXPECT_EQ(v[0], v[1]);
    EXPECT_EQ(v[3], 255);
    return static_cast<double>(v[0]);
  };
  // 255 * (ambient + diffuse * cos(angle between normal and light)).
  EXPECT_NEAR(centreGrey({{0, 0, 1}, 0.3, 0.6}), 255 * 0.9, 2.0);
  EXPECT_NEAR(centreGrey({{std::sqrt(3.0), 0, 1}, 0.3, 0.6}), 255 * 0.6, 2.0);  // 60 degrees
  EXPECT_NEAR(centreGrey({{0, 0, -1}, 0.3, 0.6}), 255 * 0.3, 2.0);  // from behind: ambient only
  EXPECT_NEAR(centreGrey({{0, 5, 5}, 0.2, 0.5}), 255 * (0.2 + 0.5 * std::sqrt(0.5)), 2.0);
}

TEST(OffscreenRenderer, SupersamplingSoftensEdgesOnly) {
  OffscreenRenderer plain(texturedSquare());
  OffscreenRenderer smooth(texturedSquare(), RenderOptions{4});
  const Camera camera = testCamera();
  const Pose pose = Pose::fromDegrees(0, 0, 23, {0, 0, -500});
  const RenderResult a = plain.render(pose, camera, kFlat);
  const RenderResult b = smooth.render(pose, camera, kFlat);
  int partial = 0;
  for (int y = 0; y < 200; ++y) {
    for (int x = 0; x < 200; ++x) {
      const uchar alpha = b.bgra.at<cv::Vec4b>(y, x)[3];
      partial += alpha > 0 && alpha < 255;
    }
  }
  EXPECT_GT(partial, 100);  // the rotated square's edges are anti-aliased
  EXPECT_NEAR(cv::sum(a.bgra)[3], cv::sum(b.bgra)[3], 0.01 * cv::sum(a.bgra)[3]);
  // Interior colour is unchanged.
  const Eigen::Vector2d p = projectPoint({-25, 25, 0}, pose, camera);
  const cv::Vec3b c = bgrAt(b.bgra, p);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], test::kTopLeft[i], 2);
}

TEST(OffscreenRenderer, ThreadsRenderTheSameAsOneThread) {
  const TexturedMesh mesh = texturedSquare();
  const Camera camera = testCamera(128);
  std::vector<Pose> poses;
  for (int i = 0; i < 12; ++i) {
    poses.push_back(Pose::fromDegrees(3.0 * i - 15, 5.0 * i - 30, i, {0, 0, -450}));
  }
  std::vector<RenderResult> sequential;
  {
    OffscreenRenderer renderer(mesh);
    for (const Pose& pose : poses) sequential.push_back(renderer.render(pose, camera));
  }
  constexpr int kThreads = 3;
  // Each thread goes through the poses in its own order, so renders that leaked into each other
  // (shared buffers or state) would show.
  std::vector<std::vector<RenderResult>> parallel(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      OffscreenRenderer renderer(mesh);
      for (std::size_t i = 0; i < poses.size() * 3; ++i) {
        const Pose& pose = poses[(i + 5 * static_cast<std::size_t>(t)) % poses.size()];
        parallel[static_cast<std::size_t>(t)].push_back(renderer.render(pose, camera));
      }
    });
  }
  for (auto& thread : threads) thread.join();
  for (std::size_t t = 0; t < parallel.size(); ++t) {
    const auto& results = parallel[t];
    ASSERT_EQ(results.size(), poses.size() * 3);
    for (std::size_t i = 0; i < results.size(); ++i) {
      const RenderResult& expected = sequential[(i + 5 * t) % poses.size()];
      EXPECT_EQ(cv::norm(results[i].bgra, expected.bgra, cv::NORM_INF), 0.0);
      cv::Mat a = results[i].depthZeroBackground();
      cv::Mat b = expected.depthZeroBackground();
      EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
    }
  }
}

TEST(OffscreenRenderer, RendererCanMoveBetweenThreads) {
  OffscreenRenderer renderer(texturedSquare());
  const Camera camera = testCamera(64);
  const Pose pose = Pose::fromDegrees(0, 10, 0, {0, 0, -500});
  const RenderResult here = renderer.render(pose, camera);
  RenderResult there;
  std::thread([&] { there = renderer.render(pose, camera); }).join();
  EXPECT_EQ(cv::norm(here.bgra, there.bgra, cv::NORM_INF), 0.0);
  // Size changes between renders.
  EXPECT_EQ(renderer.render(pose, testCamera(97)).bgra.cols, 97);
}

TEST(OffscreenRenderer, ModuleGlSymbolsDoNotLeakIntoTheProcess) {
  OffscreenRenderer renderer(texturedSquare());
  renderer.render(Pose(), testCamera(32));
  EXPECT_FALSE(renderModulePath().empty());
  EXPECT_NE(renderModuleDescription().find("OSMesa"), std::string::npos);
  EXPECT_EQ(dlsym(RTLD_DEFAULT, "glClear"), nullptr);
  EXPECT_EQ(dlsym(RTLD_DEFAULT, "glDrawElements"), nullptr);
  EXPECT_EQ(dlsym(RTLD_DEFAULT, "OSMesaCreateContextExt"), nullptr);
}

TEST(OffscreenRenderer, RejectsInvalidMeshesAndCameras) {
  TexturedMesh empty;
  empty.source = "empty.obj";
  try {
    OffscreenRenderer renderer(empty);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("empty.obj"), std::string::npos);
  }
  OffscreenRenderer renderer(texturedSquare());
  Camera bad = testCamera();
  bad.width = 0;
  EXPECT_THROW(renderer.render(Pose(), bad), Error);
}

}  // namespace
}  // namespace clm3d

namespace clm3d {
namespace {

TEST(RenderModule, SearchOrderStartsWithTheEnvironmentThenTheExecutable) {
  ::setenv("CLM3D_RENDER_MODULE", "/nonexistent/custom.so", 1);
  const auto candidates = renderModuleCandidates();
  ::unsetenv("CLM3D_RENDER_MODULE");
  ASSERT_GE(candidates.size(), 4U);
  EXPECT_EQ(candidates[0], std::filesystem::path("/nonexistent/custom.so"));
  EXPECT_EQ(candidates[1].parent_path().filename(), "clm3d");
  EXPECT_EQ(candidates[1].parent_path().parent_path().filename(), "lib");
  EXPECT_EQ(renderModuleCandidates().front(), candidates[1]);  // without the variable
}

}  // namespace
}  // namespace clm3d
