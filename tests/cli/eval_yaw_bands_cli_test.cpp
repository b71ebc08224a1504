// clm3d eval --yaw-bands through the real binary: a six-frame sequence of the fixture model's head
// at known yaws (four frames with the truth's pose, two without one), tracked with every point 5
// pixels off and one frame lost; per |yaw| band the frames, the frames tracked and the error over
// the truth's face box, with the pose-less frames banded by the model fitted to their points.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/detect/initialisation.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"
#include "core/model/model_file.hpp"
#include "core/track/track_table.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using test::runClm3d;

struct BandedSequence {
  test::TempDir dir;
  fs::path model, truth, tracked;
  std::vector<double> boxSizes;  // per frame, sqrt(w h) of the truth's points, worked out here
  BandedSequence() {
    const ClmModel& fixture = test::fitTestModel();
    model = dir / "model.clm3d";
    saveModel(fixture, model);
    const Camera camera = Camera::fromVerticalFov(640, 480, kDefaultVerticalFovDeg);
    // Yaw per frame; the last two rows are written without a pose.
    const std::vector<double> yaws{10.0, 20.0, 45.0, 75.0, -70.0, 50.0};
    TrackTable truthTable;
    truthTable.landmarkCount = 25;
    for (int f = 0; f < static_cast<int>(yaws.size()); ++f) {
      FitState state;
      state.pose =
          Pose::fromDegrees(0.0, yaws[static_cast<std::size_t>(f)], 0.0, {0.0, 0.0, -450.0}, 1.0);
      state.shape = Eigen::VectorXd::Zero(fixture.shape.modeCount());
      TrackRow row;
      row.frame = f;
      row.timestamp = f / 30.0;
      row.success = true;
      row.confidence = 1.0;
      if (f < 4) row.pose = state.pose;
      row.points = projectState(fixture, camera, state);
      const Eigen::Vector2d size =
          row.points.rowwise().maxCoeff() - row.points.rowwise().minCoeff();
      boxSizes.push_back(std::sqrt(size.x() * size.y()));
      truthTable.rows.push_back(row);
    }
    TrackTable trackedTable = truthTable;
    for (TrackRow& row : trackedTable.rows) {
      row.points.colwise() += Eigen::Vector2d(3.0, 4.0);
      row.pose.reset();
    }
    trackedTable.rows[2].success = false;  // lost at 45 degrees
    truth = dir / "truth.csv";
    tracked = dir / "tracked.csv";
    writeTrackTable(truth, truthTable);
    writeTrackTable(tracked, trackedTable);
  }
};

TEST(EvalYawBandsCli, FramesTrackedAndBoxErrorPerBandFromTheTruthPoseOrTheFittedModel) {
  BandedSequence s;
  const std::string base = "eval --truth " + s.truth.string() + " --pred " + s.tracked.string() +
                           " --label tracker --yaw-bands 0,30,60,90";
  // From the truth's pose alone: the two pose-less frames are in no band.
  const auto plain = runClm3d(base);
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_TRUE(test::contains(plain.output, "2 frames in no band")) << plain.output;
  EXPECT_TRUE(test::contains(plain.output, "|yaw| 30-60  tracker  frames 1  fitted 0 (0.0%)"))
      << plain.output;

  const fs::path table = s.dir / "bands.md";
  const fs::path report = s.dir / "report.json";
  const auto result = runClm3d(base + " --model " + s.model.string() + " --out " + report.string() +
                               " --band-table " + table.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "0 frames in no band")) << result.output;
  const auto json = nlohmann::json::parse(test::readFile(report));
  const auto& bands = json["yaw_bands"]["trackers"][0]["bands"];
  ASSERT_EQ(bands.size(), 3U);
  EXPECT_EQ(json["yaw_bands"]["trackers"][0]["outside"], 0);
  // 0-30: frames 0 and 1; 30-60: frames 2 (lost) and 5 (fitted yaw 50); 60-90: frames 3 and 4.
  EXPECT_EQ(bands[0]["frames"], 2);
  EXPECT_EQ(bands[0]["fitted"], 2);
  EXPECT_NEAR(bands[0]["mean_box_error"].get<double>(),
              (5.0 / s.boxSizes[0] + 5.0 / s.boxSizes[1]) / 2.0,
              1e-6);  // the CSV rounds the points
  EXPECT_EQ(bands[1]["frames"], 2);
  EXPECT_EQ(bands[1]["fitted"], 1);
  EXPECT_EQ(bands[2]["frames"], 2);
  EXPECT_EQ(bands[2]["fitted"], 2);
  EXPECT_NEAR(bands[2]["mean_box_error"].get<double>(),
              (5.0 / s.boxSizes[3] + 5.0 / s.boxSizes[4]) / 2.0,
              1e-6);  // the CSV rounds the points
  EXPECT_TRUE(test::contains(json["yaw_bands"]["source"].get<std::string>(), "2 truth frames"));
  const std::string markdown = test::readFile(table);
  EXPECT_TRUE(test::contains(markdown, "| 60-90 | 2 | 2 (100.0%) |")) << markdown;

  const auto usage = runClm3d(base + " --bucket-by yaw --bucket-width 15");
  EXPECT_NE(usage.exitCode, 0);
}

}  // namespace
}  // namespace clm3d
