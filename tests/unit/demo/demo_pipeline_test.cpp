// Tests of core/demo/demo_pipeline (the stages of `clm3d demo`) that need no training: the heads
// written as scans with their manifest, the training-view renders with projected, depth-tested
// landmarks (the same whatever the thread count, files named by head and view), the contact sheet
// and the hidden-landmark table. Training, the test sequence and tracking run end to end in
// tests/cli/demo_cli_test.cpp. Also core/render/projected_landmarks on one of the renders.
#include "core/demo/detail/demo_pipeline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/demo/detail/procedural_heads.hpp"
#include "core/geometry/projection.hpp"
#include "core/render/projected_landmarks.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 64;

// Two heads with small textures (the default 2048 texels take seconds a head), written once for
// every test of the process.
const DemoHeads& twoHeads() {
  static const test::TempDir dir;
  static const DemoHeads heads = writeDemoHeads(2, dir / "heads", [] {
    SynthOptions options;
    options.textureSize = 256;
    return options;
  }());
  return heads;
}

bool sameImage(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

TEST(DemoPipeline, HeadsAreWrittenAsScansOfTheManifest) {
  const DemoHeads& made = twoHeads();
  ASSERT_EQ(made.heads.size(), 2u);
  ASSERT_EQ(made.meshFiles.size(), 2u);
  ASSERT_EQ(made.manifest.scans.size(), 2u);
  EXPECT_EQ(made.manifest.name, "clm3d-demo-heads");
  const std::vector<std::string> presets = expressionPresetNames();
  for (std::size_t i = 0; i < 2; ++i) {
    const ScanSource& scan = made.manifest.scans[i];
    EXPECT_EQ(scan.subject, "head-" + std::to_string(i + 1));
    EXPECT_EQ(scan.expression, presets[i]);  // the presets in turn
    EXPECT_TRUE(scan.mesh.is_absolute());
    EXPECT_TRUE(fs::is_regular_file(scan.mesh)) << scan.mesh;
    EXPECT_TRUE(fs::equivalent(scan.mesh, made.meshFiles[i]));
    // The landmark file holds the head's exact landmarks.
    const LandmarkSet read = readLandmarks(scan.landmarks);
    ASSERT_EQ(read.size(), made.heads[i].landmarks.size());
    EXPECT_LT((read.matrix() - made.heads[i].landmarks.matrix()).cwiseAbs().maxCoeff(), 1e-3);
  }
  // Different seeds, different faces.
  EXPECT_GT((made.heads[0].landmarks.matrix() - made.heads[1].landmarks.matrix()).norm(), 1.0);
}

TEST(DemoPipeline, RendersEveryViewOfEveryHeadTheSameWhateverTheThreadCount) {
  const DemoHeads& made = twoHeads();
  test::TempDir dir;
  std::mutex mutex;
  std::vector<double> fractions;
  const DemoRenders two =
      renderDemoViews(made.heads, kSize, 2, dir / "two", [&](double fraction, std::string_view) {
        std::lock_guard lock(mutex);
        fractions.push_back(fraction);
      });
  const DemoRenders one = renderDemoViews(made.heads, kSize, 1, dir / "one");
  EXPECT_EQ(two.threads, 2);
  EXPECT_EQ(one.threads, 1);
  ASSERT_EQ(two.views.size(), 15u);
  ASSERT_EQ(two.renders.size(), 30u);
  ASSERT_EQ(one.renders.size(), 30u);
  // One report per render, the share done rising to 1.
  ASSERT_EQ(fractions.size(), 30u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  for (std::size_t i = 0; i < 30; ++i) {
    EXPECT_EQ(two.renders[i].overlay.size(), cv::Size(kSize, kSize)) << i;
    EXPECT_TRUE(sameImage(two.renders[i].overlay, one.renders[i].overlay)) << i;
    EXPECT_EQ(two.renders[i].hidden, one.renders[i].hidden) << i;
  }
  // Files named by head and view: the render and its projected points.
  const std::string frontal = demoViewName({0.0, 0.0});
  EXPECT_EQ(frontal, "yaw+0_pitch+0");
  EXPECT_EQ(demoViewName({30.0, -60.0}), "yaw-60_pitch+30");
  for (const std::string head : {"head-1", "head-2"}) {
    EXPECT_TRUE(fs::is_regular_file(dir / "two" / (head + "_" + frontal + ".png"))) << head;
    const LandmarkSet points = readLandmarks(dir / "two" / (head + "_" + frontal + ".pts"));
    EXPECT_EQ(points.size(), 25);
    for (int i = 0; i < points.size(); ++i) {
      ASSERT_TRUE(points.has(i)) << i;
      EXPECT_GE(points.point(i).x(), 0.0) << i;  // framed on the face: inside the image
      EXPECT_LT(points.point(i).x(), kSize) << i;
    }
  }
}

TEST(DemoPipeline, TurnedViewsHideTheFarSideAndTheTableSaysWhich) {
  const DemoHeads& made = twoHeads();
  test::TempDir dir;
  const DemoRenders renders = renderDemoViews({made.heads[0]}, kSize, 0, dir.path());
  const Scheme& scheme = Scheme::thesis25();
  const auto viewIndex = [&](double pitch, double yaw) {
    for (std::size_t v = 0; v < renders.views.size(); ++v) {
      if (renders.views[v].pitchDeg == pitch && renders.views[v].yawDeg == yaw) return v;
    }
    ADD_FAILURE() << "no view " << pitch << ", " << yaw;
    return std::size_t{0};
  };
  const auto hiddenNames = [&](std::size_t v) {
    std::vector<std::string> names;
    for (const int i : renders.renders[v].hidden) names.push_back(scheme.id(i));
    return names;
  };
  const auto contains = [](const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  EXPECT_TRUE(renders.renders[viewIndex(0, 0)].hidden.empty());
  // Turned 60 degrees to image -x, the right earlobe is behind the head, the left one in view.
  const std::vector<std::string> right = hiddenNames(viewIndex(0, -60));
  EXPECT_TRUE(contains(right, "right_earlobe"));
  EXPECT_FALSE(contains(right, "left_earlobe"));
  const std::vector<std::string> left = hiddenNames(viewIndex(0, 60));
  EXPECT_TRUE(contains(left, "left_earlobe"));
  EXPECT_FALSE(contains(left, "right_earlobe"));

  const std::string table = formatHiddenLandmarks(renders, 0);
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 15);
  EXPECT_NE(table.find("  yaw+0_pitch+0    0\n"), std::string::npos) << table;
  EXPECT_NE(table.find("right_earlobe"), std::string::npos) << table;
  EXPECT_THROW(formatHiddenLandmarks(renders, 1), std::out_of_range);

  // Five tiles to a row: a sheet three rows of renders tall at least.
  const cv::Mat sheet = demoContactSheet(renders);
  EXPECT_GE(sheet.cols, 5 * kSize);
  EXPECT_GE(sheet.rows, 3 * kSize);
}

TEST(ProjectedLandmarks, MissingPointsStayMissingAndHiddenOnesCanBeDropped) {
  const SynthHead& head = twoHeads().heads[0];
  LandmarkSet model = head.landmarks;
  const int missing = 3;
  model.setMissing(missing);
  const Camera camera = Camera::fromVerticalFov(96, 96, 30.0, 100.0, 3000.0);
  Pose pose = Pose::fromDegrees(0.0, 60.0, 0.0);
  const Eigen::Vector3d centroid = head.landmarks.centroid();
  pose.translation = -(pose.rotation() * centroid);
  pose.translation.z() -= 600.0;
  OffscreenRenderer renderer(head.mesh);
  const RenderResult render = renderer.render(pose, camera);
  const ProjectedLandmarks projected = projectLandmarks(model, render, pose, camera);
  ASSERT_EQ(projected.points.size(), model.size());
  ASSERT_EQ(projected.visible.size(), static_cast<std::size_t>(model.size()));
  EXPECT_FALSE(projected.points.has(missing));
  EXPECT_FALSE(projected.visible[missing]);
  EXPECT_EQ(std::count(projected.hidden.begin(), projected.hidden.end(), missing), 0);
  ASSERT_FALSE(projected.hidden.empty());  // turned 60 degrees: some points are behind the head
  for (int i = 0; i < model.size(); ++i) {
    if (i == missing) continue;
    const Eigen::Vector2d expected = projectPoint(model.point(i), pose, camera);
    EXPECT_LT((projected.points.point(i).head<2>() - expected).norm(), 1e-9) << i;
    const bool hidden = std::count(projected.hidden.begin(), projected.hidden.end(), i) > 0;
    EXPECT_EQ(projected.visible[static_cast<std::size_t>(i)], !hidden) << i;
    EXPECT_EQ(projected.visible[static_cast<std::size_t>(i)], render.isVisible(model.point(i)));
  }
  const LandmarkSet visibleOnly = visiblePointsOnly(projected);
  EXPECT_EQ(visibleOnly.presentCount(),
            projected.points.presentCount() - static_cast<int>(projected.hidden.size()));
  for (const int i : projected.hidden) EXPECT_FALSE(visibleOnly.has(i)) << i;
}

TEST(ProceduralHeads, SeedsInARowWithTheExpressionsInTurnAndTheirTiles) {
  test::TempDir dir;
  SynthOptions options;
  options.textureSize = 256;
  options.faceStepDegrees = 2.0;
  std::vector<WrittenHead> written;
  std::vector<std::size_t> triangles;
  HeadTiles tiles;
  writeProceduralHeads(7, 3, {"smile", "neutral"}, options, dir / "out",
                       [&](const WrittenHead& head, SynthHead&& made) {
                         written.push_back(head);
                         triangles.push_back(made.mesh.triangleCount());
                         if (written.size() == 1) tiles = trainingViewTiles(made, head.seed, 64);
                       });
  ASSERT_EQ(written.size(), 3u);
  const std::vector<std::string> expected{"smile", "neutral", "smile"};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(written[i].seed, 7 + i);
    EXPECT_EQ(written[i].expression, expected[i]);
    EXPECT_EQ(written[i].mesh, dir / "out" / ("head-" + std::to_string(7 + i) + ".obj"));
    EXPECT_TRUE(fs::is_regular_file(written[i].mesh));
    EXPECT_EQ(readLandmarks(written[i].landmarks).size(), 25);
    EXPECT_GT(triangles[i], 0u);
  }
  ASSERT_EQ(tiles.tiles.size(), 15u);
  ASSERT_EQ(tiles.captions.size(), 15u);
  EXPECT_EQ(tiles.captions.front(), "#7 y-60 p-30");
  EXPECT_EQ(tiles.tiles.front().size(), cv::Size(64, 64));
  // Something drawn in every tile (the background is transparent).
  for (const cv::Mat& tile : tiles.tiles) {
    std::vector<cv::Mat> channels;
    cv::split(tile, channels);
    EXPECT_GT(cv::countNonZero(channels[3]), 64 * 64 / 10);
  }

  // A bad expression name is refused before anything is written.
  EXPECT_THROW(writeProceduralHeads(1, 2, {"smile", "grin"}, options, dir / "bad", {}), InputError);
  EXPECT_FALSE(fs::exists(dir / "bad"));
  EXPECT_THROW(writeProceduralHeads(1, 2, {}, options, dir / "none", {}), InputError);
}

}  // namespace
}  // namespace clm3d
