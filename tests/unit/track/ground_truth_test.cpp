// The ground-truth set: starting from a tracker's output (padding to the video's frames),
// keyframes, linear interpolation between them with missing landmarks, the CSV + .pts round trip,
// plain tracker CSVs, and the errors for bad keyframe cells, frames and point counts.
#include "core/track/ground_truth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "core/common/error.hpp"
#include "core/common/number_text.hpp"
#include "core/scheme/landmark_file.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// A tracker output of 3 landmarks for frames 0, 1 and 3 of a 25 fps video.
TrackTable sampleTrack() {
  TrackTable track;
  track.landmarkCount = 3;
  for (const int frame : {0, 1, 3}) {
    TrackRow row;
    row.frame = frame;
    row.timestamp = frame / 25.0;
    row.success = true;
    row.confidence = 0.7;
    row.view = 2;
    row.pose = Pose::fromDegrees(0.0, 10.0 * frame, 0.0);
    row.points.resize(2, 3);
    row.points << 10.0 + frame, 20.0, 30.0, 40.0, 50.0 + frame, 60.0;
    track.rows.push_back(row);
  }
  return track;
}

Eigen::Matrix2Xd points(double x0, double y0, double x1, double y1, double x2, double y2) {
  Eigen::Matrix2Xd p(2, 3);
  p << x0, x1, x2, y0, y1, y2;
  return p;
}

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(GroundTruth, FromTrackPadsToTheFrameCount) {
  const auto set = GroundTruthSet::fromTrack(sampleTrack(), 6);
  ASSERT_EQ(set.frameCount(), 6);
  ASSERT_EQ(set.keyframe.size(), 6u);
  EXPECT_EQ(set.keyframeCount(), 0);
  for (int frame = 0; frame < 6; ++frame) {
    const auto& row = set.table.rows[static_cast<std::size_t>(frame)];
    EXPECT_EQ(row.frame, frame);
    EXPECT_NEAR(row.timestamp, frame / 25.0, 1e-12) << frame;  // padded rows: the track's rate
    const bool tracked = frame == 0 || frame == 1 || frame == 3;
    EXPECT_EQ(row.success, tracked) << frame;
    EXPECT_EQ(row.pose.has_value(), tracked) << frame;
    EXPECT_EQ(row.points.cols(), 3);
    EXPECT_EQ(std::isnan(row.points(0, 0)), !tracked) << frame;
  }
  EXPECT_EQ(set.table.rows[3].points(0, 0), 13.0);
  EXPECT_EQ(set.table.rows[3].view, 2);

  EXPECT_NE(errorOf([] {
              GroundTruthSet::fromTrack(sampleTrack(), 3);
            }).find("the track has frame 3, but the video has 3 frames"),
            std::string::npos);
  EXPECT_NE(errorOf([] { GroundTruthSet::fromTrack(sampleTrack(), -1); }), "no error");
}

TEST(GroundTruth, KeyframesSetAndClear) {
  auto set = GroundTruthSet::fromTrack(sampleTrack(), 5);
  set.setKeyframe(1, points(1, 2, kNan, kNan, 5, 6));
  const auto& row = set.table.rows[1];
  EXPECT_TRUE(set.keyframe[1]);
  EXPECT_TRUE(row.success);
  EXPECT_EQ(row.confidence, 1.0);
  EXPECT_EQ(row.view, -1);
  EXPECT_FALSE(row.pose.has_value());
  EXPECT_TRUE(std::isnan(row.points(0, 1)));
  EXPECT_EQ(row.points(1, 2), 6.0);

  set.setKeyframe(4, points(kNan, kNan, kNan, kNan, kNan, 3));  // half a point is none
  EXPECT_FALSE(set.table.rows[4].success);
  EXPECT_TRUE(std::isnan(set.table.rows[4].points(0, 2)));
  EXPECT_EQ(set.keyframeCount(), 2);

  set.clearKeyframe(1);
  EXPECT_FALSE(set.keyframe[1]);
  EXPECT_EQ(set.table.rows[1].points(0, 0), 1.0);  // the points stay

  EXPECT_NE(errorOf([&] {
              set.setKeyframe(5, points(1, 2, 3, 4, 5, 6));
            }).find("frame 5 is outside 0..4"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { set.clearKeyframe(-1); }).find("frame -1 is outside"), std::string::npos);
  EXPECT_NE(errorOf([&] {
              set.setKeyframe(0, Eigen::Matrix2Xd::Zero(2, 4));
            }).find("frame 0 was given 4 points, the ground truth has 3"),
            std::string::npos);
}

// The tracker's visibility stays with its rows; corrected points have none (it described the fit).
TEST(GroundTruth, KeyframesDropTheTrackersVisibility) {
  TrackTable track = sampleTrack();
  for (auto& row : track.rows) {
    row.visibility = {Visibility::Visible, Visibility::Hidden, Visibility::Visible};
  }
  auto set = GroundTruthSet::fromTrack(track, 5);
  EXPECT_EQ(set.table.rows[0].visibility, track.rows[0].visibility);
  EXPECT_TRUE(set.table.rows[2].visibility.empty());  // a frame the track did not have
  set.setKeyframe(1, points(1, 2, 3, 4, 5, 6));
  EXPECT_TRUE(set.table.rows[1].visibility.empty());
  const auto text = formatTrackTable(set.table);
  EXPECT_NE(text.find(",1,0,1\n"), std::string::npos) << text;      // frame 0
  EXPECT_NE(text.find(",6.0000,,,\n"), std::string::npos) << text;  // frame 1, now a keyframe
}

TEST(GroundTruth, FirstKeyframeSetsTheLandmarkCountOfAnEmptySet) {
  auto set = GroundTruthSet::fromTrack(TrackTable{}, 3);
  set.setKeyframe(2, points(1, 2, 3, 4, 5, 6));
  EXPECT_EQ(set.table.landmarkCount, 3);
  EXPECT_EQ(set.table.rows[0].points.cols(), 3);
  EXPECT_TRUE(std::isnan(set.table.rows[0].points(0, 0)));
}

TEST(GroundTruth, InterpolatesLinearlyBetweenKeyframes) {
  auto set = GroundTruthSet::fromTrack(sampleTrack(), 8);
  set.setKeyframe(1, points(10, 20, 30, 40, kNan, kNan));
  set.setKeyframe(5, points(50, 60, kNan, kNan, 7, 8));
  set.setKeyframe(6, points(0, 0, 0, 0, 0, 0));  // adjacent: nothing between
  EXPECT_EQ(set.interpolateKeyframes(), 3);      // frames 2, 3, 4

  for (const int frame : {2, 3, 4}) {
    const auto& row = set.table.rows[static_cast<std::size_t>(frame)];
    const double t = (frame - 1) / 4.0;
    EXPECT_NEAR(row.points(0, 0), 10 + 40 * t, 1e-12) << frame;
    EXPECT_NEAR(row.points(1, 0), 20 + 40 * t, 1e-12) << frame;
    // Missing in one keyframe or the other: missing.
    EXPECT_TRUE(std::isnan(row.points(0, 1))) << frame;
    EXPECT_TRUE(std::isnan(row.points(0, 2))) << frame;
    EXPECT_NEAR(row.timestamp, (1 + 4 * t) / 25.0, 1e-12);
    EXPECT_TRUE(row.success);
    EXPECT_EQ(row.confidence, 1.0);
    EXPECT_FALSE(row.pose.has_value());
    EXPECT_EQ(row.view, -1);
    EXPECT_FALSE(set.keyframe[static_cast<std::size_t>(frame)]);
  }
  // Outside the keyframes nothing changes: frame 0 is still the tracker's.
  EXPECT_EQ(set.table.rows[0].points(0, 0), 10.0);
  EXPECT_TRUE(set.table.rows[0].pose.has_value());
  EXPECT_TRUE(std::isnan(set.table.rows[7].points(0, 0)));
}

TEST(GroundTruth, SavesAndLoadsWithKeyframesAndPtsFiles) {
  test::TempDir dir;
  auto set = GroundTruthSet::fromTrack(sampleTrack(), 5);
  set.setKeyframe(0, points(1.25, 2.5, kNan, kNan, 5, 6));
  set.setKeyframe(4, points(9, 10, 11, 12, 13, 14));
  set.interpolateKeyframes();
  saveGroundTruth(dir / "gt.csv", set, dir / "pts");

  const auto text = test::readFile(dir / "gt.csv");
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "frame,timestamp,success,confidence,view,tx,ty,tz,scale,pitch,yaw,roll,x_1,x_2,x_3,"
            "y_1,y_2,y_3,keyframe");
  const auto back = loadGroundTruth(dir / "gt.csv");
  ASSERT_EQ(back.frameCount(), 5);
  EXPECT_EQ(back.keyframe, (std::vector<bool>{true, false, false, false, true}));
  EXPECT_TRUE(back.table.extraColumns.empty());
  for (int frame = 0; frame < 5; ++frame) {
    const auto& a = set.table.rows[static_cast<std::size_t>(frame)];
    const auto& b = back.table.rows[static_cast<std::size_t>(frame)];
    EXPECT_EQ(b.success, a.success);
    for (int i = 0; i < 3; ++i) {
      if (std::isnan(a.points(0, i))) {
        EXPECT_TRUE(std::isnan(b.points(0, i)));
      } else {
        EXPECT_NEAR(b.points(0, i), a.points(0, i), 5.1e-5);
        EXPECT_NEAR(b.points(1, i), a.points(1, i), 5.1e-5);
      }
    }
  }

  // One .pts per frame, 0-based in memory once read back (1-based on disk).
  for (int frame = 0; frame < 5; ++frame) {
    EXPECT_TRUE(std::filesystem::exists(dir / "pts" / groundTruthPtsName(frame))) << frame;
  }
  EXPECT_EQ(groundTruthPtsName(42), "frame_000042.pts");
  const auto pts = readLandmarks(dir / "pts" / "frame_000000.pts");
  ASSERT_EQ(pts.size(), 3);
  EXPECT_NEAR(pts.point(0).x(), 1.25, 1e-9);
  EXPECT_NEAR(pts.point(0).y(), 2.5, 1e-9);
  EXPECT_FALSE(pts.has(1));
  EXPECT_NE(test::readFile(dir / "pts" / "frame_000000.pts").find("2.25 3.5"), std::string::npos);
}

TEST(GroundTruth, PlainTrackerCsvLoadsWithoutKeyframesAndPadsGaps) {
  test::TempDir dir;
  writeTrackTable(dir / "tracks.csv", sampleTrack());
  const auto set = loadGroundTruth(dir / "tracks.csv");
  EXPECT_EQ(set.frameCount(), 4);
  EXPECT_EQ(set.keyframeCount(), 0);
  EXPECT_FALSE(set.table.rows[2].success);
  EXPECT_TRUE(std::isnan(set.table.rows[2].points(1, 1)));
  EXPECT_EQ(set.table.rows[3].points(1, 1), 53.0);
}

TEST(GroundTruth, BadFilesNameTheFileAndLine) {
  test::TempDir dir;
  const auto file = dir / "gt.csv";
  const auto loadError = [&](const std::string& text) {
    test::writeFile(file, text);
    return errorOf([&] { loadGroundTruth(file); });
  };
  const std::string header = "frame,success,x_1,y_1,keyframe\n";
  EXPECT_EQ(loadError(header + "0,1,1,2,1\n\n1,1,1,2,yes\n"),
            file.string() + ":4: column keyframe: \"yes\" is not 0 or 1");
  EXPECT_EQ(loadError(header + "0,1,1,2,\n"),
            file.string() + ":2: column keyframe: \"\" is not 0 or 1");
  EXPECT_EQ(
      loadError(header + "0,1,1,2,0\n5000000,1,1,2,0\n"),
      file.string() + ":3: frame 5000000 is beyond the 1000000 frames a ground truth may have");
  EXPECT_EQ(loadError(header + "0,1,1,2\n").rfind(file.string() + ":2: expected 5 cells", 0), 0u);
  EXPECT_NE(errorOf([&] { loadGroundTruth(dir / "absent.csv"); }).find("absent.csv"),
            std::string::npos);
}

TEST(GroundTruth, SaveRejectsAnInconsistentSet) {
  test::TempDir dir;
  auto set = GroundTruthSet::fromTrack(sampleTrack(), 4);
  set.keyframe.pop_back();
  EXPECT_THROW(saveGroundTruth(dir / "gt.csv", set), Error);
  EXPECT_FALSE(std::filesystem::exists(dir / "gt.csv"));
}

}  // namespace
}  // namespace clm3d
