// clm3d eval through the real binary: two predictions compared (text, JSON, plots, report file),
// and broken or mismatched inputs exit 1 with a message naming the file.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/track/track_table.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::runClm3d;

// A thesis25 ground truth (eye centres 60 pixels apart) and predictions off by `shift` pixels plus
// a little per-frame variation.
TrackTable face(int frames, double shift, int landmarks = 25) {
  TrackTable table;
  table.landmarkCount = landmarks;
  for (int f = 0; f < frames; ++f) {
    TrackRow row;
    row.frame = f;
    row.timestamp = f / 25.0;
    row.success = true;
    row.confidence = 1.0;
    row.view = 7;
    row.pose = Pose::fromDegrees(0.0, f, 0.0);
    row.points.resize(2, landmarks);
    const double wobble = shift > 0.0 ? 0.4 * ((f * 7) % 5) : 0.0;
    for (int i = 0; i < landmarks; ++i) {
      row.points(0, i) = 200.0 + 4.0 * i + shift + wobble;
      row.points(1, i) = 300.0 + 2.0 * (i % 5);
    }
    if (landmarks == 25) {
      row.points.col(7) = Eigen::Vector2d(220.0 + shift + wobble, 250.0);
      row.points.col(10) = Eigen::Vector2d(280.0 + shift + wobble, 250.0);
    }
    table.rows.push_back(row);
  }
  return table;
}

struct EvalFiles {
  test::TempDir dir;
  std::string truth, a, b;
  EvalFiles() {
    truth = (dir / "gt.csv").string();
    a = (dir / "multi.csv").string();
    b = (dir / "single.csv").string();
    writeTrackTable(truth, face(30, 0.0));
    writeTrackTable(a, face(30, 2.0));
    writeTrackTable(b, face(30, 6.0));
  }
};

TEST(EvalCli, ComparesTwoPredictionsWithPlots) {
  EvalFiles files;
  const auto plots = files.dir / "plots";
  const auto result =
      runClm3d("eval --truth " + files.truth + " --pred " + files.a + " --pred " + files.b +
               " --label multi-view --label single-view --plot " + plots.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const std::string& expected : std::vector<std::string>{
           "ground truth: " + files.truth + " (30 frames, scheme thesis25",
           "\nmulti-view (" + files.a + ")", "\nsingle-view (" + files.b + ")",
           "frames: 30/30 predicted, 30 succeeded (0 with an error above 0.30), 30 scored, 30 "
           "converged",
           "error: mean ", "convergence rate 100.0%, points within 0.18: 100.0% (750/750)",
           "regions (mean point error): left_eye", "jaw", "Welch's t-test on frame errors",
           "means differ at the 5% level", "plots: " + (plots / "cdf.png").string()}) {
    EXPECT_NE(result.output.find(expected), std::string::npos)
        << "missing \"" << expected << "\" in:\n"
        << result.output;
  }
  for (const char* name : {"cdf.png", "error-per-frame.png", "regions.png"}) {
    ASSERT_TRUE(std::filesystem::exists(plots / name)) << name;
    EXPECT_GT(std::filesystem::file_size(plots / name), 5000u) << name;
  }
}

TEST(EvalCli, JsonGoesToStdoutAndTheReportFile) {
  EvalFiles files;
  const auto out = files.dir / "report.json";
  // stderr (where the report file is mentioned) is discarded inside the group, so the output
  // must be the JSON document alone.
  const auto result = test::runCommand(
      "{ " + (test::binaryDir() / "bin" / "clm3d").string() + " eval --truth " + files.truth +
      " --pred " + files.a + " " + files.b + " --json --out " + out.string() + " 2>/dev/null; }");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output);
  ASSERT_EQ(json["predictions"].size(), 2u);
  EXPECT_EQ(json["predictions"][0]["label"], "multi");
  EXPECT_EQ(json["predictions"][1]["label"], "single");
  // 2 (+ wobble 0..1.6) pixels of 60 versus 6 (+ wobble).
  EXPECT_NEAR(json["predictions"][0]["error"]["mean"].get<double>(), (2.0 + 0.8) / 60.0, 0.005);
  EXPECT_NEAR(json["predictions"][1]["error"]["mean"].get<double>(), (6.0 + 0.8) / 60.0, 0.005);
  EXPECT_EQ(json["comparison"]["test"], "welch_t");
  EXPECT_LT(json["comparison"]["p"].get<double>(), 1e-6);
  EXPECT_EQ(nlohmann::json::parse(test::readFile(out)), json);
}

TEST(EvalCli, ThreePredictionsGetAnAnova) {
  EvalFiles files;
  const auto c = (files.dir / "third.csv").string();
  writeTrackTable(c, face(30, 4.0));
  const auto result =
      runClm3d("eval --truth " + files.truth + " --pred " + files.a + " " + files.b + " " + c);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("one-way ANOVA on frame errors: F(2, 87)"), std::string::npos)
      << result.output;
}

TEST(EvalCli, BrokenOrMissingFilesExitOneNamingTheFile) {
  EvalFiles files;
  const auto broken = (files.dir / "broken.csv").string();
  test::writeFile(broken, "frame,success,x_1,y_1\n0,1,abc,2\n");
  auto result = runClm3d("eval --truth " + files.truth + " --pred " + broken);
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find(broken + ":2: column x_1"), std::string::npos) << result.output;

  const auto absent = (files.dir / "absent.csv").string();
  result = runClm3d("eval --truth " + absent + " --pred " + files.a);
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find(absent), std::string::npos) << result.output;
}

TEST(EvalCli, DifferentLandmarkCountsAreAClearError) {
  EvalFiles files;
  const auto other = (files.dir / "ibug.csv").string();
  writeTrackTable(other, face(30, 0.0, 68));
  const auto result = runClm3d("eval --truth " + files.truth + " --pred " + other);
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find(other + ": has 68 landmarks but the ground truth " + files.truth +
                               " has 25"),
            std::string::npos)
      << result.output;
  // The truth itself must match the scheme.
  const auto wrongScheme = runClm3d("eval --truth " + other + " --pred " + other);
  EXPECT_EQ(wrongScheme.exitCode, 1);
  EXPECT_NE(wrongScheme.output.find("but scheme thesis25 has 25"), std::string::npos)
      << wrongScheme.output;
}

TEST(EvalCli, MissingPredictionIsAUsageError) {
  EvalFiles files;
  EXPECT_EQ(runClm3d("eval --truth " + files.truth).exitCode, 2);
}

}  // namespace
}  // namespace clm3d
