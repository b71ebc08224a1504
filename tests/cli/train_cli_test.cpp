// clm3d train end to end on a tiny procedural manifest: exit codes, the model file, the report,
// and a bad manifest named in the error.
#include <gtest/gtest.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "core/model/model_file.hpp"
#include "core/train/train_options.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

constexpr const char* kTinyManifest = R"({
  "version": 1,
  "name": "tiny",
  "procedural": [{"seeds": [1, 2], "texture_size": 256, "face_step_degrees": 2.0}]
})";

TEST(TrainCli, TrainsASmallModelThatLoads) {
  test::TempDir dir;
  test::writeFile(dir / "tiny.json", kTinyManifest);
  const auto result = test::runClm3d(
      "train --dataset " + (dir / "tiny.json").string() + " --out " + (dir / "m.clm3d").string() +
      " --report " + (dir / "report").string() +
      " --views-yaw -60,0,60 --views-pitch 0 --scales 2 --patch-size 8 --samples 2 --threads 2");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const ClmModel model = loadModel(dir / "m.clm3d");
  EXPECT_EQ(model.views.size(), 3u);
  EXPECT_EQ(model.views[0].scales.size(), 2u);
  EXPECT_NE(result.output.find("trained multi-view 3D CLM"), std::string::npos) << result.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "report" / "mean-patches-scale0.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "report" / "hidden-landmarks.png"));
}

// --expert-units: every expert of the model has that many units (a neural field, or the linear
// expert padded where the field lost on held-out regions), the file is of the current format
// (version 3 brought the units), and `clm3d info` reads it back.
TEST(TrainCli, NeuralFieldExpertsAreWrittenAndReadBack) {
  test::TempDir dir;
  test::writeFile(dir / "tiny.json", kTinyManifest);
  const auto result = test::runClm3d(
      "train --dataset " + (dir / "tiny.json").string() + " --out " + (dir / "n.clm3d").string() +
      " --views-yaw 0 --views-pitch 0 --scales 1 --patch-size 8 --samples 2 --expert-units 3");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const ClmModel model = loadModel(dir / "n.clm3d");
  int fields = 0;
  for (const PatchModel& patches : model.views.front().scales) {
    ASSERT_EQ(patches.experts.size(), patches.landmarks.size());
    for (const PatchExpert& expert : patches.experts) {
      EXPECT_EQ(expert.units(), 3);
      if (expert.alpha.tail(2).cwiseAbs().sum() > 0.0f) ++fields;
    }
  }
  std::cout << "[ " << fields << " experts kept their neural field ]\n";
  const auto info = test::runClm3d("info " + (dir / "n.clm3d").string());
  ASSERT_EQ(info.exitCode, 0) << info.output;
  EXPECT_TRUE(test::contains(info.output, "format version " + std::to_string(kModelFormatVersion)))
      << info.output;
  EXPECT_TRUE(test::contains(info.output, "point refiner: none")) << info.output;
  const auto refused =
      test::runClm3d("train --dataset " + (dir / "tiny.json").string() + " --out " +
                     (dir / "x.clm3d").string() + " --expert-units 17");
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_TRUE(test::contains(refused.output, "--expert-units")) << refused.output;
}

TEST(TrainCli, SingleViewBaseline) {
  test::TempDir dir;
  test::writeFile(dir / "tiny.json", kTinyManifest);
  const auto result =
      test::runClm3d("train --single-view --dataset " + (dir / "tiny.json").string() + " --out " +
                     (dir / "b.clm3d").string() + " --scales 1 --patch-size 8 --samples 2");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const ClmModel model = loadModel(dir / "b.clm3d");
  EXPECT_TRUE(model.singleView);
  EXPECT_EQ(model.views.size(), 1u);
}

TEST(TrainCli, BadManifestExitsOneNamingTheFile) {
  test::TempDir dir;
  test::writeFile(dir / "bad.json", "{ not json");
  const auto result = test::runClm3d("train --dataset " + (dir / "bad.json").string() + " --out " +
                                     (dir / "m.clm3d").string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("bad.json"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "m.clm3d"));
}

// The options come from core's table (core/train/train_options): their help shows the
// TrainSettings defaults, and a run that sets only a few options trains with the defaults of all
// the others (the model records the settings it was trained with).
TEST(TrainCli, OptionsDefaultToTheTrainSettingsDefaults) {
  const auto help = test::runClm3d("train --help");
  ASSERT_EQ(help.exitCode, 0) << help.output;
  for (const TrainOption& option : trainOptions()) {
    const auto at = help.output.find("--" + option.name + " ");
    ASSERT_NE(at, std::string::npos) << option.name;
    const std::string line = help.output.substr(at, help.output.find('\n', at) - at);
    if (option.kind != OptionKind::Flag) {  // CLI11 writes "--scales INT:INT in [1 - 5]=3"
      EXPECT_NE(line.find("=" + option.defaultText()), std::string::npos) << line;
    }
  }
  test::TempDir dir;
  test::writeFile(dir / "tiny.json", kTinyManifest);
  const auto result = test::runClm3d("train --dataset " + (dir / "tiny.json").string() + " --out " +
                                     (dir / "d.clm3d").string() +
                                     " --views-yaw 0 --views-pitch 0 --scales 1 --patch-size 8"
                                     " --samples 1 --expert-radius 1 --threads 2");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  TrainSettings expected;
  expected.yawsDeg = {0};
  expected.pitchesDeg = {0};
  expected.scales = 1;
  expected.patchSize = 8;
  expected.samplesPerView = 1;
  expected.expertRadius = 1;
  auto stored = nlohmann::json::parse(loadModel(dir / "d.clm3d").settingsJson);
  auto wanted = nlohmann::json::parse(expected.toJson());
  stored.erase("augmentation");  // the manifest's (its default background), not an option
  wanted.erase("augmentation");
  EXPECT_EQ(stored, wanted);
}

TEST(TrainCli, OutOfRangeOptionsAreRefusedNamingTheOption) {
  const std::string run = "train --dataset d.json --out m.clm3d ";
  const auto scales = test::runClm3d(run + "--scales 7");
  EXPECT_EQ(scales.exitCode, 2) << scales.output;
  EXPECT_NE(scales.output.find("--scales"), std::string::npos) << scales.output;
  const auto yaw = test::runClm3d(run + "--views-yaw 0,120");
  EXPECT_EQ(yaw.exitCode, 1) << yaw.output;
  EXPECT_NE(yaw.output.find("--views-yaw"), std::string::npos) << yaw.output;
  EXPECT_NE(yaw.output.find("-90..90"), std::string::npos) << yaw.output;
}

TEST(TrainCli, MissingOptionsAreAUsageError) {
  EXPECT_EQ(test::runClm3d("train --out x.clm3d").exitCode, 2);
}

TEST(TrainCli, ShapeMirroringLimitAndModeCap) {
  test::TempDir dir;
  test::writeFile(dir / "tiny.json", kTinyManifest);
  const auto result = test::runClm3d(
      "train --dataset " + (dir / "tiny.json").string() + " --out " + (dir / "s.clm3d").string() +
      " --views-yaw 0 --views-pitch 0 --scales 1 --patch-size 8 --samples 3 --mirror-shapes"
      " --shape-limit 2.5 --texture-max-modes 2");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const ClmModel model = loadModel(dir / "s.clm3d");
  EXPECT_DOUBLE_EQ(model.shape.limitSd, 2.5);
  EXPECT_LE(model.views[0].scales[0].pca.modeCount(), 2);
  // With mirrored copies the mean shape is left/right symmetric: a mirror pair's x are opposite.
  const Eigen::Matrix3Xd& mean = model.shape.meanShape;
  constexpr int kLeftEyeCentre = 7;
  constexpr int kRightEyeCentre = 10;
  EXPECT_NEAR(mean(0, kLeftEyeCentre), -mean(0, kRightEyeCentre), 1e-6);
  EXPECT_NEAR(mean(1, kLeftEyeCentre), mean(1, kRightEyeCentre), 1e-6);
}

}  // namespace
}  // namespace clm3d
