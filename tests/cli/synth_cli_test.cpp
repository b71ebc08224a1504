// clm3d synth end to end: a procedural head's sequence writes the video, the truth, the visibility
// table and the description; a scan written by synth-head goes through the --mesh path, and
// --scale scales it as training does; bad ranges,
// missing files and conflicting options fail with clear messages and the documented exit codes.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/eval/synthetic_sequence.hpp"
#include "core/track/track_table.hpp"
#include "core/video/video_reader.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

// Small and fast (the suite also runs under ASan): a coarse head and tiny frames.
const std::string kSmall =
    " --texture-size 256 --face-step 2 --size 160x120 --face-size 30 --supersample 1";

TEST(SynthCli, HeadSeedWritesVideoTruthVisibilityAndDescription) {
  const test::TempDir dir;
  const fs::path out = dir / "seq";
  const auto result =
      test::runClm3d("synth --head-seed 3 --yaw-range 0:4 --out " + out.string() + kSmall);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "5 frames 160x120")) << result.output;
  for (const char* name : {"sequence.avi", "truth.csv", "truth-visibility.csv", "sequence.json"}) {
    EXPECT_TRUE(fs::exists(out / name)) << name;
  }
  EXPECT_EQ(VideoReader(out / "sequence.avi").frameCount(), 5);
  const TrackTable truth = readTrackTable(out / "truth.csv");
  EXPECT_EQ(truth.landmarkCount, 25);
  ASSERT_EQ(truth.rows.size(), 5U);
  ASSERT_TRUE(truth.rows[4].pose.has_value());
  EXPECT_NEAR(degrees(truth.rows[4].pose->yaw), 4.0, 1e-6);
  EXPECT_EQ(readVisibilityTable(out / "truth-visibility.csv").size(), 5U);
  const std::string json = test::readFile(out / "sequence.json");
  EXPECT_TRUE(test::contains(json, "\"seed\": 3")) << json;
  EXPECT_TRUE(test::contains(json, "\"expression\": \"neutral\"")) << json;
}

TEST(SynthCli, ScanFromSynthHeadWithNegativeRangeAndMp4) {
  const test::TempDir dir;
  const auto head = test::runClm3d("synth-head --seed 4 --texture-size 256 --face-step 2 --out " +
                                   dir.path().string());
  ASSERT_EQ(head.exitCode, 0) << head.output;
  const fs::path out = dir / "seq";
  const auto result = test::runClm3d(
      "synth --mesh " + (dir / "head-4.obj").string() + " --landmarks " +
      (dir / "head-4.ljson").string() + " --yaw-range=-10:10 --step 10 --format mp4 --out " +
      out.string() + " --size 160x120 --face-size 30 --supersample 1");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(fs::exists(out / "sequence.mp4"));
  EXPECT_FALSE(fs::exists(out / "sequence.avi"));
  const TrackTable truth = readTrackTable(out / "truth.csv");
  ASSERT_EQ(truth.rows.size(), 3U);
  // The frontal frame (yaw 0) has the requested face size between the eye centres (8 and 11).
  const auto& frontal = truth.rows[1];
  EXPECT_NEAR((frontal.points.col(7) - frontal.points.col(10)).norm(), 30.0, 0.1);
  const std::string json = test::readFile(out / "sequence.json");
  EXPECT_TRUE(test::contains(json, "\"kind\": \"scan\"")) << json;
  EXPECT_TRUE(test::contains(json, "head-4.obj")) << json;
}

// --scale turns file units into millimetres as a manifest's scans[i].scale does (core's
// loadScanSubject): the head twice as large stands twice as far away for the same face size, and
// the description records the scale.
TEST(SynthCli, ScaleMultipliesTheScanAsTrainingDoes) {
  const test::TempDir dir;
  const auto head = test::runClm3d("synth-head --seed 5 --texture-size 256 --face-step 2 --out " +
                                   dir.path().string());
  ASSERT_EQ(head.exitCode, 0) << head.output;
  const auto run = [&](const std::string& name, const std::string& scale) {
    const auto result = test::runClm3d(
        "synth --mesh " + (dir / "head-5.obj").string() + " --landmarks " +
        (dir / "head-5.ljson").string() + " --yaw-range 0 --scale " + scale + " --out " +
        (dir / name).string() + " --size 160x120 --face-size 30 --supersample 1");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    return readTrackTable(dir / name / "truth.csv");
  };
  const TrackTable one = run("one", "1");
  const TrackTable two = run("two", "2");
  ASSERT_EQ(one.rows.size(), 1U);
  ASSERT_EQ(two.rows.size(), 1U);
  ASSERT_TRUE(one.rows[0].pose && two.rows[0].pose);
  EXPECT_NEAR(two.rows[0].pose->translation.z() / one.rows[0].pose->translation.z(), 2.0, 1e-3);
  EXPECT_NEAR((two.rows[0].points - one.rows[0].points).cwiseAbs().maxCoeff(), 0.0, 0.05);
  EXPECT_TRUE(test::contains(test::readFile(dir / "two" / "sequence.json"), "\"scale\": 2"));
  EXPECT_FALSE(test::contains(test::readFile(dir / "one" / "sequence.json"), "\"scale\""));
  const auto bad = test::runClm3d("synth --mesh " + (dir / "head-5.obj").string() +
                                  " --landmarks " + (dir / "head-5.ljson").string() +
                                  " --scale 0 --out " + (dir / "bad").string());
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_TRUE(test::contains(bad.output, "--scale")) << bad.output;
}

TEST(SynthCli, BadYawRangeIsAUsageErrorNamingTheOption) {
  const test::TempDir dir;
  for (const char* range : {"0:abc", "0:500", "sixty"}) {
    const auto result = test::runClm3d("synth --head-seed 1 --yaw-range " + std::string(range) +
                                       " --out " + dir.path().string());
    EXPECT_EQ(result.exitCode, 2) << range << ": " << result.output;
    EXPECT_TRUE(test::contains(result.output, "--yaw-range")) << result.output;
    EXPECT_TRUE(test::contains(result.output, range)) << result.output;
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(SynthCli, MissingMeshExitsOneNamingTheFile) {
  const test::TempDir dir;
  const fs::path mesh = dir / "absent.obj";
  // Real landmarks (core reads them before the mesh), an absent mesh.
  const auto result = test::runClm3d("synth --mesh " + mesh.string() + " --landmarks " +
                                     test::fixturePath("james/james.thesis25.ljson").string() +
                                     " --out " + (dir / "seq").string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_TRUE(test::contains(result.output, mesh.string())) << result.output;
  EXPECT_FALSE(fs::exists(dir / "seq"));
}

TEST(SynthCli, ConflictingOrMissingSubjectOptionsAreUsageErrors) {
  const test::TempDir dir;
  const std::string out = " --out " + (dir / "seq").string();
  const auto none = test::runClm3d("synth" + out);
  EXPECT_EQ(none.exitCode, 2) << none.output;
  EXPECT_TRUE(test::contains(none.output, "--head-seed")) << none.output;
  const auto both = test::runClm3d("synth --head-seed 1 --mesh a.obj --landmarks a.ljson" + out);
  EXPECT_EQ(both.exitCode, 2) << both.output;
  const auto expression =
      test::runClm3d("synth --mesh a.obj --landmarks a.ljson --expression smile" + out);
  EXPECT_EQ(expression.exitCode, 2) << expression.output;
  EXPECT_TRUE(test::contains(expression.output, "--expression")) << expression.output;
  const auto size = test::runClm3d("synth --head-seed 1 --size 641x480" + out);
  EXPECT_EQ(size.exitCode, 2) << size.output;
  EXPECT_TRUE(test::contains(size.output, "even")) << size.output;
  const auto unknown = test::runClm3d("synth --head-seed 1 --expression grin" + out + kSmall);
  EXPECT_EQ(unknown.exitCode, 1) << unknown.output;
  EXPECT_TRUE(test::contains(unknown.output, "grin")) << unknown.output;
  EXPECT_FALSE(fs::exists(dir / "seq"));
}

}  // namespace
}  // namespace clm3d
