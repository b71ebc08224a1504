// ClmModel::validate names the first inconsistency; nearestView picks the closest view centre.
#include "core/model/clm_model.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"
#include "tests/support/tiny_model.hpp"

namespace clm3d {
namespace {

std::string validationError(const ClmModel& model) {
  try {
    model.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ClmModel, TinyModelIsValid) {
  EXPECT_EQ(validationError(test::makeTinyModel()), "");
}

TEST(ClmModel, ValidateNamesTheInconsistentField) {
  {
    ClmModel model = test::makeTinyModel();
    model.views[1].visible.pop_back();
    EXPECT_NE(validationError(model).find("views[1].visible"), std::string::npos);
  }
  {
    ClmModel model = test::makeTinyModel();
    model.views[0].visible[2] = true;  // visible but without a patch
    EXPECT_NE(validationError(model).find("views[0].scales[0].landmarks"), std::string::npos);
  }
  {
    ClmModel model = test::makeTinyModel();
    model.views[2].scales[1].pca.mean.conservativeResize(5);
    EXPECT_NE(validationError(model).find("views[2].scales[1].pca.mean"), std::string::npos);
  }
  {
    ClmModel model = test::makeTinyModel();
    model.views[1].scales[0].alpha[3][2] = 1.5f;
    EXPECT_NE(validationError(model).find("views[1].scales[0].alpha[3]"), std::string::npos);
  }
  {
    ClmModel model = test::makeTinyModel();
    model.shape.modes(0, 0) = std::numeric_limits<double>::infinity();
    EXPECT_NE(validationError(model).find("shape.modes"), std::string::npos);
  }
  {
    ClmModel model = test::makeTinyModel();
    model.schemeJson = "{";
    EXPECT_NE(validationError(model).find("field scheme"), std::string::npos);
  }
  {
    ClmModel model = test::makeTinyModel();
    model.singleView = true;
    EXPECT_NE(validationError(model).find("single-view"), std::string::npos);
  }
  {
    ClmModel model = test::makeTinyModel();
    model.settingsJson = "[1, 2]";
    EXPECT_NE(validationError(model).find("field settings"), std::string::npos);
  }
}

TEST(ClmModel, NearestViewPicksTheClosestCentre) {
  const ClmModel model = test::makeTinyModel();  // yaw -30, 0, 30 at pitch 0
  EXPECT_EQ(model.nearestView(0, -40), 0);
  EXPECT_EQ(model.nearestView(10, 12), 1);
  EXPECT_EQ(model.nearestView(-20, 25), 2);
  EXPECT_EQ(ClmModel{}.nearestView(0, 0), -1);
}

}  // namespace
}  // namespace clm3d
