// clm3d synth --photo --yaw-range through the real binary (core/profile): a render of procedural
// head 7 with its projected points, profiled with that head's own mesh (--dense-head-seed 7) and
// turned. The frame at the photo's own pose puts the points back where the photo has them; a
// range gives one frame per step with the truth's yaw, the far side's points hidden at the ends;
// options that move the photo in the image plane, a missing dense face and --beside are usage
// errors naming the option; a dense model that is not there exits 1 naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/geometry/pose.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/track_table.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using test::runClm3d;

// The photo: head 7 rendered at yaw 10 into 320x320 (a small texture and a coarse mesh: quick), and
// its 25 projected points.
struct TurnedPhotoFiles {
  test::TempDir dir;
  fs::path photo, points;
  TurnedPhotoFiles() {
    const fs::path head = dir / "head";
    const auto made =
        runClm3d("synth-head --seed 7 --texture-size 256 --face-step 1.5 --out " + head.string());
    EXPECT_EQ(made.exitCode, 0) << made.output;
    photo = dir / "photo.png";
    points = dir / "photo.pts";
    const auto rendered =
        runClm3d("render --mesh " + (head / "head-7.obj").string() + " --landmarks " +
                 (head / "head-7.ljson").string() + " --yaw 10 --size 320 --out " + photo.string() +
                 " --out-landmarks " + points.string());
    EXPECT_EQ(rendered.exitCode, 0) << rendered.output;
  }
  // A coarse dense head (the profile needs the landmarks, not the mesh's detail), no supersampling.
  std::string base() const {
    return "synth --photo " + photo.string() + " --landmarks " + points.string() +
           " --face-step 3 --texture-size 256 --supersample 1 ";
  }
};

const TurnedPhotoFiles& turnedPhotoFiles() {
  static const TurnedPhotoFiles files;
  return files;
}

TEST(SynthTurnedPhotoCli, ThePhotosOwnPoseGivesThePhotosPoints) {
  const TurnedPhotoFiles& f = turnedPhotoFiles();
  const fs::path out = f.dir / "own";
  // The photo is at yaw 10 (the fit finds about that): one frame there.
  const auto result =
      runClm3d(f.base() + "--yaw-range 10:10 --dense-head-seed 7 --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "1 frames 320x320")) << result.output;
  EXPECT_TRUE(test::contains(result.output, "25 points fitted")) << result.output;
  const TrackTable truth = readTrackTable(out / "truth.csv");
  ASSERT_EQ(truth.rows.size(), 1U);
  const LandmarkSet photo = readLandmarks(f.points);
  double sum = 0.0;
  for (int i = 0; i < 25; ++i) {
    sum += (truth.rows[0].points.col(i) - photo.point(i).head<2>()).norm();
  }
  // The fit's residual is under a pixel; the frame's yaw is the range's, not the fitted one.
  EXPECT_LT(sum / 25.0, 2.5);
}

TEST(SynthTurnedPhotoCli, ARangeGivesAFramePerStepWithItsYawAndHidesTheFarSide) {
  const TurnedPhotoFiles& f = turnedPhotoFiles();
  const fs::path out = f.dir / "range";
  const fs::path sheet = f.dir / "sheet.png";
  const auto result =
      runClm3d(f.base() + "--yaw-range=-60:60 --step 30 --dense-head-seed 7 --contact-sheet " +
               sheet.string() + " --sheet-frames 3 --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(fs::exists(sheet));
  EXPECT_TRUE(fs::exists(out / "sequence.json"));
  const TrackTable truth = readTrackTable(out / "truth.csv");
  ASSERT_EQ(truth.rows.size(), 5U);
  for (std::size_t k = 0; k < truth.rows.size(); ++k) {
    const TrackRow& row = truth.rows[k];
    ASSERT_TRUE(row.pose.has_value());
    EXPECT_NEAR(degrees(row.pose->yaw), -60.0 + 30.0 * static_cast<double>(k), 1e-6);
    EXPECT_TRUE(row.success);
  }
  // Turned 60 degrees either way, each side hides some of the far side's points; frontal none.
  const std::string visibility = test::readFile(out / "truth-visibility.csv");
  EXPECT_TRUE(test::contains(result.output, "hidden landmark-frames")) << result.output;
  EXPECT_FALSE(test::contains(result.output, " 0 hidden landmark-frames")) << result.output;
  EXPECT_FALSE(visibility.empty());
}

TEST(SynthTurnedPhotoCli, MovingOptionsAMissingDenseFaceAndBesideAreUsageErrors) {
  const TurnedPhotoFiles& f = turnedPhotoFiles();
  const std::string out = " --out " + (f.dir / "bad").string();
  const auto frames = runClm3d(f.base() + "--yaw-range 0:20 --dense-head-seed 7 --frames 10" + out);
  EXPECT_EQ(frames.exitCode, 2) << frames.output;
  EXPECT_TRUE(test::contains(frames.output, "--frames")) << frames.output;
  const auto noFace = runClm3d(f.base() + "--yaw-range 0:20" + out);
  EXPECT_EQ(noFace.exitCode, 2) << noFace.output;
  EXPECT_TRUE(test::contains(noFace.output, "--dense-model")) << noFace.output;
  const auto beside = runClm3d(f.base() + "--yaw-range 0:20 --dense-head-seed 7 --beside " +
                               f.photo.string() + " --beside-landmarks " + f.points.string() + out);
  EXPECT_EQ(beside.exitCode, 2) << beside.output;
  EXPECT_TRUE(test::contains(beside.output, "--beside")) << beside.output;
  const fs::path absent = f.dir / "absent-ict.tar.xz";
  const auto missing = runClm3d(f.base() + "--yaw-range 0:20 --dense-model " + absent.string() +
                                " --dense-vertices " + f.points.string() + out);
  EXPECT_EQ(missing.exitCode, 1) << missing.output;
  EXPECT_TRUE(test::contains(missing.output, absent.string())) << missing.output;
  EXPECT_FALSE(fs::exists(f.dir / "bad" / "truth.csv"));
}

}  // namespace
}  // namespace clm3d
