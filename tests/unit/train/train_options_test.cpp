// The training option table: names unique and described, every option's default is the
// TrainSettings default and reads back to it, and TrainSettings::validate refuses a value out of
// an option's range with an error naming the option.
#include "core/train/train_options.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

std::string validationError(const TrainSettings& settings) {
  try {
    settings.validate();
  } catch (const InputError& error) {
    return error.what();
  }
  return {};
}

TEST(TrainOptions, NamesAreUniqueAndDescribed) {
  std::set<std::string> names;
  for (const TrainOption& option : trainOptions()) {
    EXPECT_TRUE(names.insert(option.name).second) << option.name;
    EXPECT_FALSE(option.label.empty()) << option.name;
    EXPECT_FALSE(option.group.empty()) << option.name;
    EXPECT_FALSE(option.help.empty()) << option.name;
    if (option.kind != OptionKind::Flag && option.kind != OptionKind::Choice) {
      EXPECT_LT(option.minimum, option.maximum) << option.name;
    }
  }
  for (const char* name : {"views-yaw", "views-pitch", "scales", "patch-size", "samples",
                           "texture-variance", "shape-variance", "expert-radius", "seed"}) {
    EXPECT_NE(findTrainOption(name), nullptr) << name;
  }
  EXPECT_EQ(findTrainOption("no-such-option"), nullptr);
}

TEST(TrainOptions, DefaultsAreTheSettingsDefaults) {
  const TrainSettings defaults;
  EXPECT_EQ(findTrainOption("views-yaw")->defaultText(), "-60,-30,0,30,60");
  EXPECT_EQ(findTrainOption("scales")->defaultText(), std::to_string(defaults.scales));
  EXPECT_EQ(findTrainOption("samples")->defaultText(), std::to_string(defaults.samplesPerView));
  EXPECT_EQ(findTrainOption("no-mirror")->defaultText(), "false");
  EXPECT_EQ(findTrainOption("shape-limit")->defaultText(), "3");
  EXPECT_TRUE(changedOptions(trainOptions(), defaults).empty());
  EXPECT_NO_THROW(defaults.validate());
  for (const TrainOption& option : trainOptions()) {
    TrainSettings settings;
    option.set(settings, option.defaultText());
    EXPECT_EQ(settings.toJson(), defaults.toJson()) << option.name;
    EXPECT_TRUE(changedOptions(trainOptions(), settings).empty()) << option.name;
  }
}

TEST(TrainOptions, TextsSetTheFieldsTheyName) {
  TrainSettings settings;
  findTrainOption("views-yaw")->set(settings, "-45, 0,45");
  findTrainOption("no-mirror")->set(settings, "true");
  findTrainOption("shape-limit")->set(settings, "2.5");
  findTrainOption("samples")->set(settings, "7");
  EXPECT_EQ(settings.yawsDeg, (std::vector<double>{-45, 0, 45}));
  EXPECT_FALSE(settings.mirrorRightViews);
  EXPECT_DOUBLE_EQ(settings.shape.limitSd, 2.5);
  EXPECT_EQ(settings.samplesPerView, 7);
  const auto changed = changedOptions(trainOptions(), settings);
  EXPECT_EQ(changed.size(), 4u);
  EXPECT_EQ(changed.at("views-yaw"), "-45,0,45");
}

TEST(TrainOptions, ValuesOutOfRangeAreRefusedNamingTheOption) {
  TrainSettings settings;
  settings.scales = 7;
  std::string error = validationError(settings);
  EXPECT_NE(error.find("training settings"), std::string::npos) << error;
  EXPECT_NE(error.find("--scales"), std::string::npos) << error;
  EXPECT_NE(error.find("1..5"), std::string::npos) << error;

  settings = TrainSettings{};
  settings.yawsDeg = {0, 100};
  error = validationError(settings);
  EXPECT_NE(error.find("--views-yaw"), std::string::npos) << error;

  settings = TrainSettings{};
  settings.pitchesDeg.clear();
  EXPECT_NE(validationError(settings).find("--views-pitch"), std::string::npos);

  settings = TrainSettings{};
  settings.shape.limitSd = 0.1;
  EXPECT_NE(validationError(settings).find("--shape-limit"), std::string::npos);

  settings = TrainSettings{};
  settings.perturbation.ambient = 0.5;
  EXPECT_NE(validationError(settings).find("--ambient-jitter"), std::string::npos);

  TrainSettings parsed;
  EXPECT_THROW(findTrainOption("patch-size")->set(parsed, "3"), InputError);
  EXPECT_THROW(findTrainOption("patch-size")->set(parsed, "eight"), InputError);
  EXPECT_THROW(findTrainOption("views-pitch")->set(parsed, "0, up"), InputError);
  EXPECT_THROW(findTrainOption("views-pitch")->set(parsed, ","), InputError);
  EXPECT_THROW(findTrainOption("single-view")->set(parsed, "maybe"), InputError);
  EXPECT_EQ(parsed.toJson(), TrainSettings{}.toJson());
}

}  // namespace
}  // namespace clm3d
