// clm3d truth through the real binary: a tracker output padded to the video, keyframes from .pts
// files, interpolation, the CSV (read back by clm3d eval) and the .pts per frame; and bad inputs
// exit 1 naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "core/track/ground_truth.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::runClm3d;

// A thesis25 face whose points are shifted right by dx pixels (eye centres 60 pixels apart).
Eigen::Matrix2Xd face(double dx) {
  Eigen::Matrix2Xd points(2, 25);
  for (int i = 0; i < 25; ++i) points.col(i) = Eigen::Vector2d(200.0 + 4.0 * i + dx, 300.0 + i);
  points.col(7) = Eigen::Vector2d(220.0 + dx, 250.0);
  points.col(10) = Eigen::Vector2d(280.0 + dx, 250.0);
  return points;
}

void writeFacePts(const std::filesystem::path& path, double dx) {
  LandmarkSet set(25, 2);
  const auto points = face(dx);
  for (int i = 0; i < 25; ++i) set.set(i, Eigen::Vector2d(points.col(i)));
  writeLandmarks(path, set, Scheme::thesis25());
}

// A tracker output with frames 0..3 of a 10-frame video.
void writeTracks(const std::filesystem::path& path) {
  TrackTable table;
  table.landmarkCount = 25;
  for (int frame = 0; frame < 4; ++frame) {
    TrackRow row;
    row.frame = frame;
    row.timestamp = frame / 25.0;
    row.success = true;
    row.confidence = 0.8;
    row.view = 3;
    row.points = face(1.0);
    table.rows.push_back(row);
  }
  writeTrackTable(path, table);
}

TEST(TruthCli, BuildsInterpolatedGroundTruthWithPtsFiles) {
  test::TempDir dir;
  writeTracks(dir / "tracks.csv");
  writeFacePts(dir / "k2.pts", 0.0);
  writeFacePts(dir / "k8.pts", 12.0);
  const auto out = dir / "gt.csv";
  const auto pts = dir / "pts";
  const auto result = runClm3d("truth --in " + (dir / "tracks.csv").string() +
                               " --frames 10 --keyframe 2=" + (dir / "k2.pts").string() +
                               " --keyframe 8=" + (dir / "k8.pts").string() +
                               " --interpolate --out " + out.string() + " --pts " + pts.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("(10 frames, 2 keyframes, 25 landmarks)"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("interpolated: 5 frames"), std::string::npos) << result.output;

  const auto set = loadGroundTruth(out);
  ASSERT_EQ(set.frameCount(), 10);
  EXPECT_EQ(set.keyframe, (std::vector<bool>{false, false, true, false, false, false, false, false,
                                             true, false}));
  EXPECT_NEAR(set.table.rows[5].points(0, 0), 200.0 + 6.0, 1e-4);  // halfway from 0 to 12
  EXPECT_NEAR(set.table.rows[0].points(0, 0), 201.0, 1e-4);        // the tracker's, untouched
  EXPECT_FALSE(set.table.rows[9].success);                         // padding
  for (int frame = 0; frame < 10; ++frame) {
    EXPECT_TRUE(std::filesystem::exists(pts / groundTruthPtsName(frame))) << frame;
  }
  const auto frame5 = readLandmarks(pts / "frame_000005.pts");
  EXPECT_NEAR(frame5.point(0).x(), 206.0, 1e-4);

  // clm3d eval reads it as a ground truth as it is.
  const auto eval =
      runClm3d("eval --truth " + out.string() + " --pred " + (dir / "tracks.csv").string());
  EXPECT_EQ(eval.exitCode, 0) << eval.output;

  // Editing it again: the keyframes are kept, one is cleared.
  const auto again =
      runClm3d("truth --in " + out.string() + " --clear-keyframe 8 --out " + out.string());
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_NE(again.output.find("(10 frames, 1 keyframes, 25 landmarks)"), std::string::npos)
      << again.output;
}

TEST(TruthCli, StartsEmptyFromAFrameCount) {
  test::TempDir dir;
  writeFacePts(dir / "a.pts", 0.0);
  const auto out = dir / "gt.csv";
  const auto result = runClm3d("truth --frames 3 --keyframe 1=" + (dir / "a.pts").string() +
                               " --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto set = loadGroundTruth(out);
  EXPECT_EQ(set.frameCount(), 3);
  EXPECT_TRUE(set.keyframe[1]);
  EXPECT_FALSE(set.table.rows[0].success);
}

TEST(TruthCli, BadInputsExitOneNamingTheFile) {
  test::TempDir dir;
  writeTracks(dir / "tracks.csv");
  const auto tracks = (dir / "tracks.csv").string();
  const auto out = (dir / "gt.csv").string();

  test::writeFile(dir / "broken.csv", "frame,success,x_1,y_1,keyframe\n0,1,1,2,maybe\n");
  auto result = runClm3d("truth --in " + (dir / "broken.csv").string() + " --out " + out);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("broken.csv:2: column keyframe: \"maybe\" is not 0 or 1"),
            std::string::npos)
      << result.output;

  test::writeFile(dir / "small.pts", "version: 1\nn_points: 3\n{\n1 2\n3 4\n5 6\n}\n");
  result = runClm3d("truth --in " + tracks + " --keyframe 1=" + (dir / "small.pts").string() +
                    " --out " + out);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("small.pts: has 3 points, the ground truth has 25"),
            std::string::npos)
      << result.output;

  result = runClm3d("truth --in " + tracks + " --frames 2 --out " + out);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("tracks.csv: has 4 frames, more than --frames 2"), std::string::npos)
      << result.output;

  result = runClm3d("truth --in " + tracks + " --clear-keyframe 7 --out " + out);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("frame 7 is outside 0..3"), std::string::npos) << result.output;

  result = runClm3d("truth --in " + tracks + " --keyframe seven --out " + out);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("is not FRAME=FILE"), std::string::npos) << result.output;

  result = runClm3d("truth --out " + out);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace clm3d
