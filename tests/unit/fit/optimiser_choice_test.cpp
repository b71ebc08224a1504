// "auto", the default optimiser: rlms for a model trained with photos (experts and a checked point
// refiner), fastncc for the thesis's models; the fitter reports what it chose (tracker_test: the
// tracker).
#include <gtest/gtest.h>

#include <algorithm>

#include "core/fit/fitter.hpp"
#include "core/fit/optimiser.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d {
namespace {

ClmModel withCheckedRefiner(ClmModel model) {
  test::giveCheckedRefiner(model);
  return model;
}

TEST(OptimiserChoice, AutoIsTheDefaultAndOneOfTheChoices) {
  EXPECT_EQ(FitSettings{}.optimiser, kAutoOptimiser);
  const auto& choices = optimiserChoices();
  EXPECT_EQ(choices.front(), kAutoOptimiser);
  for (const std::string& name : optimiserNames())
    EXPECT_NE(std::find(choices.begin(), choices.end(), name), choices.end()) << name;
}

TEST(OptimiserChoice, AutoPicksRlmsOnlyForAModelWithExpertsAndACheckedRefiner) {
  const ClmModel& plain = test::fitTestModel();
  ASSERT_TRUE(plain.refiner.empty());
  ASSERT_TRUE(plain.views.front().scales.front().hasExperts());
  EXPECT_EQ(resolveOptimiser(kAutoOptimiser, plain), "fastncc");

  const ClmModel checked = withCheckedRefiner(plain);
  EXPECT_EQ(resolveOptimiser(kAutoOptimiser, checked), "rlms");

  ClmModel unchecked = checked;
  unchecked.refiner.check = {};
  EXPECT_EQ(resolveOptimiser(kAutoOptimiser, unchecked), "fastncc");

  ClmModel noExperts = checked;
  noExperts.views.back().scales.back().experts.clear();
  EXPECT_EQ(resolveOptimiser(kAutoOptimiser, noExperts), "fastncc");

  // A name given is kept, whatever the model.
  EXPECT_EQ(resolveOptimiser("powell", checked), "powell");
  EXPECT_EQ(resolveOptimiser("rlms", plain), "rlms");
}

TEST(OptimiserChoice, TheFitterReportsWhatAutoChose) {
  const ClmModel checked = withCheckedRefiner(test::fitTestModel());
  const test::FitScene scene = test::makeFitScene(checked, 0.0, 0.0);
  EXPECT_EQ(Fitter(checked, scene.camera).settings().optimiser, "rlms");
  EXPECT_EQ(Fitter(test::fitTestModel(), scene.camera).settings().optimiser, "fastncc");
}

}  // namespace
}  // namespace clm3d
