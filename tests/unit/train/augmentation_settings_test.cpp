// The manifest's `augmentation` object: parsed into AugmentationSettings, absent = the defaults
// (a cluttered background, every other effect off), bad values rejected with the field named;
// TrainSettings records it in the model's settings JSON only when an effect is on, and validates
// its ranges.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/common/error.hpp"
#include "core/dataset/manifest.hpp"
#include "core/train/train_settings.hpp"

namespace clm3d {
namespace {

DatasetManifest parseWith(const std::string& augmentation) {
  return parseManifest(
      R"({"version": 1, "procedural": [{"seeds": "1"}], "augmentation": )" + augmentation + "}",
      "/tmp/m.json");
}

std::string errorOf(const std::string& augmentation) {
  try {
    parseWith(augmentation);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(AugmentationSettings, AbsentMeansOnlyTheClutteredBackground) {
  const DatasetManifest m =
      parseManifest(R"({"version": 1, "procedural": [{"seeds": "1"}]})", "/tmp/m.json");
  for (const AugmentationSettings& a : {m.augmentation, parseWith("{}").augmentation}) {
    EXPECT_EQ(a.background, AugmentationBackground::Clutter);
    AugmentationSettings rest = a;
    rest.background = AugmentationBackground::None;
    EXPECT_FALSE(rest.any());
  }
  EXPECT_FALSE(parseWith(R"({"background": "none"})").augmentation.any());
  EXPECT_FALSE(AugmentationSettings::off().any());
}

TEST(AugmentationSettings, ParsesEveryField) {
  const AugmentationSettings a =
      parseWith(R"({"background": "clutter", "colour_jitter": 0.2, "white_balance": 0.1,
                    "blur_sigma_max": 1.5, "noise_sd": 0.03, "jpeg_quality_min": 40,
                    "light_angle_max": 75, "shadows": true, "probability": 0.8})")
          .augmentation;
  EXPECT_EQ(a.background, AugmentationBackground::Clutter);
  EXPECT_DOUBLE_EQ(a.colourJitter, 0.2);
  EXPECT_DOUBLE_EQ(a.whiteBalance, 0.1);
  EXPECT_DOUBLE_EQ(a.blurSigmaMax, 1.5);
  EXPECT_DOUBLE_EQ(a.noiseSd, 0.03);
  EXPECT_EQ(a.jpegQualityMin, 40);
  EXPECT_DOUBLE_EQ(a.lightAngleMaxDeg, 75);
  EXPECT_TRUE(a.shadows);
  EXPECT_DOUBLE_EQ(a.probability, 0.8);
  EXPECT_TRUE(a.any());
}

TEST(AugmentationSettings, BadValuesNameTheField) {
  const auto expectError = [](const std::string& json, const std::string& field) {
    const std::string what = errorOf(json);
    EXPECT_NE(what.find("/tmp/m.json"), std::string::npos) << what;
    EXPECT_NE(what.find("field augmentation." + field + ":"), std::string::npos) << what;
  };
  expectError(R"({"noise_sd": 0.7})", "noise_sd");
  EXPECT_NE(errorOf(R"({"noise_sd": 0.7})").find("must be in [0, 0.5]"), std::string::npos);
  expectError(R"({"colour_jitter": -0.1})", "colour_jitter");
  expectError(R"({"white_balance": "a lot"})", "white_balance");
  expectError(R"({"blur_sigma_max": 9})", "blur_sigma_max");
  expectError(R"({"jpeg_quality_min": 3})", "jpeg_quality_min");
  expectError(R"({"jpeg_quality_min": 99})", "jpeg_quality_min");
  expectError(R"({"light_angle_max": 120})", "light_angle_max");
  expectError(R"({"shadows": 1})", "shadows");
  expectError(R"({"probability": 1.5})", "probability");
  expectError(R"({"background": "photos"})", "background");
  expectError(R"({"nosie_sd": 0.1})", "nosie_sd");
  EXPECT_NE(errorOf("[1]").find("field augmentation: expected an object"), std::string::npos)
      << errorOf("[1]");
}

TEST(AugmentationSettings, RecordedInTheModelSettingsOnlyWhenOn) {
  TrainSettings settings;
  EXPECT_EQ(settings.augmentation.background, AugmentationBackground::Clutter);  // the default
  EXPECT_TRUE(nlohmann::json::parse(settings.toJson()).contains("augmentation"));
  settings.augmentation = AugmentationSettings::off();
  EXPECT_FALSE(nlohmann::json::parse(settings.toJson()).contains("augmentation"));
  settings.augmentation.noiseSd = 0.02;
  settings.augmentation.shadows = true;
  const auto json = nlohmann::json::parse(settings.toJson());
  ASSERT_TRUE(json.contains("augmentation"));
  EXPECT_DOUBLE_EQ(json["augmentation"]["noise_sd"].get<double>(), 0.02);
  EXPECT_TRUE(json["augmentation"]["shadows"].get<bool>());
  EXPECT_EQ(json["augmentation"]["background"].get<std::string>(), "none");
}

TEST(AugmentationSettings, ValidateRejectsOutOfRangeValues) {
  TrainSettings settings;
  settings.augmentation.jpegQualityMin = 2;
  EXPECT_THROW(settings.validate(), InputError);
  settings.augmentation.jpegQualityMin = 50;
  EXPECT_NO_THROW(settings.validate());
  settings.augmentation.probability = -0.5;
  EXPECT_THROW(settings.validate(), InputError);
}

}  // namespace
}  // namespace clm3d
