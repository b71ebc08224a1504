// clm3d info MODEL through the real binary: a summary of a valid model (exit 0), one message
// naming the file for a truncated or missing one (exit 1).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/model/model_file.hpp"
#include "tests/support/test_support.hpp"
#include "tests/support/tiny_model.hpp"

namespace clm3d {
namespace {

using test::runClm3d;

TEST(InfoCli, SummarisesAModel) {
  test::TempDir dir;
  const auto path = dir / "tiny.clm3d";
  saveModel(test::makeTinyModel(42), path);
  const auto result = runClm3d("info " + path.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const std::string& expected : std::vector<std::string>{
           "scheme: tiny5, 5 landmarks", "multi-view 3D, 3 view(s)", "shape model: 3D, 5 points",
           "view 0: pitch 0, yaw -30, 4/5 landmarks visible; hidden: 3 right_eye",
           "view 2: pitch 0, yaw 30 (mirrored), 4/5 landmarks visible; hidden: 2 left_eye",
           "scale 1: 4x4 patches", "trained from: tiny.json", "seed 42",
           std::to_string(std::filesystem::file_size(path)) + " bytes"}) {
    EXPECT_NE(result.output.find(expected), std::string::npos)
        << "missing \"" << expected << "\" in:\n"
        << result.output;
  }
}

// It says where a fit's probability of being right comes from (docs/fitting.md#one-confidence):
// the built-in curves for a model without calibrations, the views' curves for rlms once they have
// them.
TEST(InfoCli, SaysWhereAFitsProbabilityComesFrom) {
  test::TempDir dir;
  ClmModel model = test::makeTinyModel(42);
  saveModel(model, dir / "plain.clm3d");
  const auto plain = runClm3d("info " + (dir / "plain.clm3d").string());
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_TRUE(test::contains(plain.output, "fit probability: the built-in curves")) << plain.output;
  model.views[1].calibration = LogisticCurve{12.0, -6.0};  // the frontal view: no mirror image
  saveModel(model, dir / "calibrated.clm3d");
  const auto calibrated = runClm3d("info " + (dir / "calibrated.clm3d").string());
  ASSERT_EQ(calibrated.exitCode, 0) << calibrated.output;
  EXPECT_TRUE(test::contains(calibrated.output, "rlms: the views' calibration"))
      << calibrated.output;
}

TEST(InfoCli, TruncatedModelFailsNamingTheFile) {
  test::TempDir dir;
  const auto path = dir / "cut.clm3d";
  test::writeFile(path, serializeModel(test::makeTinyModel()).substr(0, 60));
  const auto result = runClm3d("info " + path.string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find(path.string() + ": truncated"), std::string::npos) << result.output;
  const auto missing = runClm3d("info " + (dir / "absent.clm3d").string());
  EXPECT_EQ(missing.exitCode, 1) << missing.output;
  EXPECT_NE(missing.output.find("absent.clm3d"), std::string::npos) << missing.output;
}

TEST(InfoCli, MissingArgumentIsAUsageError) {
  EXPECT_EQ(runClm3d("info").exitCode, 2);
}

}  // namespace
}  // namespace clm3d
