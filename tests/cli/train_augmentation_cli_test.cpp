// clm3d train with a manifest's `augmentation` object: the model records the effects it was
// trained with, and --no-augmentation switches them all off for a run.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/model/model_file.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

constexpr const char* kAugmentedManifest = R"({
  "version": 1,
  "name": "tiny-augmented",
  "procedural": [{"seeds": [1, 2], "texture_size": 256, "face_step_degrees": 2.0}],
  "augmentation": {"background": "clutter", "noise_sd": 0.02, "jpeg_quality_min": 50,
                   "light_angle_max": 60, "shadows": true}
})";

nlohmann::json trainedSettings(const test::TempDir& dir, const std::string& extra) {
  const auto result = test::runClm3d(
      "train --dataset " + (dir / "aug.json").string() + " --out " + (dir / "m.clm3d").string() +
      " --views-yaw -30,0 --views-pitch 0 --scales 1 --patch-size 8 --samples 1 --threads 1" +
      extra);
  EXPECT_EQ(result.exitCode, 0) << result.output;
  return nlohmann::json::parse(loadModel(dir / "m.clm3d").settingsJson);
}

TEST(TrainAugmentationCli, ManifestEffectsAreRecordedAndNoAugmentationSwitchesThemOff) {
  test::TempDir dir;
  test::writeFile(dir / "aug.json", kAugmentedManifest);
  const nlohmann::json on = trainedSettings(dir, "");
  ASSERT_TRUE(on.contains("augmentation"));
  EXPECT_EQ(on["augmentation"]["background"].get<std::string>(), "clutter");
  EXPECT_TRUE(on["augmentation"]["shadows"].get<bool>());
  const nlohmann::json off = trainedSettings(dir, " --no-augmentation");
  EXPECT_FALSE(off.contains("augmentation"));
}

TEST(TrainAugmentationCli, HelpListsNoAugmentation) {
  const auto result = test::runClm3d("train --help");
  EXPECT_EQ(result.exitCode, 0);
  EXPECT_NE(result.output.find("--no-augmentation"), std::string::npos) << result.output;
}

TEST(TrainAugmentationCli, BadAugmentationFieldIsNamed) {
  test::TempDir dir;
  test::writeFile(dir / "bad.json", R"({"version": 1, "procedural": [{"seeds": "1"}],
                                        "augmentation": {"noise_sd": 0.9}})");
  const auto result = test::runClm3d("train --dataset " + (dir / "bad.json").string() + " --out " +
                                     (dir / "m.clm3d").string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("augmentation.noise_sd"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace clm3d
