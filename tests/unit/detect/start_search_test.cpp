// fitFromBestStart: a start outside the search's capture range is recovered by the grid of moved
// starts (one of which lands near the face), the most confident fit is the one returned, and with
// no grid it is the plain search; with a threshold, the grid runs only when the start's own fit
// is below it.
#include "core/detect/start_search.hpp"

#include <gtest/gtest.h>

#include "tests/support/fit_fixture.hpp"

namespace clm3d {
namespace {

double errorOf(const FitResult& fit, const test::FitScene& scene) {
  return test::meanPointError(fit.points, scene.truthPoints) / scene.interOcular;
}

TEST(StartSearch, ShiftedStartMovesTheProjectionByTheShareOfTheEyeDistance) {
  const ClmModel& model = test::fitTestModel();
  const test::FitScene scene = test::makeFitScene(model, 0.0, 0.0);
  Fitter fitter(model, scene.camera);
  const FitState moved = shiftedStart(model, fitter, scene.truth, Eigen::Vector2d(0.5, -0.25));
  const Eigen::Matrix2Xd before = fitter.project(scene.truth);
  const Eigen::Matrix2Xd after = fitter.project(moved);
  const double eyes = (before.col(7) - before.col(10)).norm();
  const Eigen::Vector2d shift = (after - before).rowwise().mean();
  EXPECT_NEAR(shift.x(), 0.5 * eyes, 0.05 * eyes);
  EXPECT_NEAR(shift.y(), -0.25 * eyes, 0.05 * eyes);
}

TEST(StartSearch, TheGridRecoversAStartOutsideTheCaptureRange) {
  const ClmModel& model = test::fitTestModel();
  const test::FitScene scene = test::makeFitScene(model, 0.0, 0.0);
  Fitter fitter(model, scene.camera);
  const FitState far = shiftedStart(model, fitter, scene.truth, Eigen::Vector2d(0.6, 0.0));

  int searches = 0;
  const FitResult alone = fitFromBestStart(fitter, model, scene.image, far, {}, &searches);
  EXPECT_EQ(searches, 1);
  const FitResult plain = fitter.fit(scene.image, far);
  EXPECT_EQ(alone.probability, plain.probability);
  EXPECT_TRUE(alone.points.isApprox(plain.points));

  StartSearchSettings grid;
  grid.steps = 1;
  grid.shift = 0.6;
  const FitResult searched = fitFromBestStart(fitter, model, scene.image, far, grid, &searches);
  EXPECT_EQ(searches, 9);  // 9 starts
  EXPECT_GE(searched.probability, alone.probability);
  EXPECT_LT(errorOf(searched, scene), 0.1) << "from the far start alone: " << errorOf(alone, scene);
  EXPECT_LT(errorOf(searched, scene), 0.5 * errorOf(alone, scene));
}

TEST(StartSearch, TheGridRunsOnlyWhenTheStartsFitIsBelowTheThreshold) {
  const ClmModel& model = test::fitTestModel();
  const test::FitScene scene = test::makeFitScene(model, 0.0, 0.0);
  Fitter fitter(model, scene.camera);
  const FitState far = shiftedStart(model, fitter, scene.truth, Eigen::Vector2d(0.6, 0.0));
  const FitResult fromTruth = fitter.fit(scene.image, scene.truth);
  const FitResult fromFar = fitter.fit(scene.image, far);
  ASSERT_GT(fromTruth.probability, fromFar.probability);
  StartSearchSettings grid;
  grid.steps = 1;
  grid.shift = 0.6;
  grid.onlyBelow = 0.5 * (fromTruth.probability + fromFar.probability);

  int searches = 0;
  const FitResult trusted =
      fitFromBestStart(fitter, model, scene.image, scene.truth, grid, &searches);
  EXPECT_EQ(searches, 1);
  EXPECT_EQ(trusted.probability, fromTruth.probability);

  const FitResult doubted = fitFromBestStart(fitter, model, scene.image, far, grid, &searches);
  EXPECT_EQ(searches, 9);
  EXPECT_LT(errorOf(doubted, scene), 0.5 * errorOf(fromFar, scene));
}

// A doubted fit is searched from the neighbouring views, unless its probability does not compare
// views (the point check's, learnt on near-frontal photos; the experts' raw response on one curve)
// and that was not asked for.
TEST(ViewSearch, DoubtedFitsAreSearchedAndOnesThatDoNotCompareViewsOnlyWhenAsked) {
  FitResult fit;
  fit.probability = 0.6;
  fit.probabilitySource = ProbabilitySource::BuiltInNccCurve;
  EXPECT_TRUE(wantsViewSearch(fit, 0.9, false));
  EXPECT_FALSE(wantsViewSearch(fit, 0.5, false)) << "not doubted";
  EXPECT_FALSE(wantsViewSearch(fit, 0.0, true)) << "off";
  for (const ProbabilitySource source :
       {ProbabilitySource::ViewCheck, ProbabilitySource::ViewCalibration}) {
    fit.probabilitySource = source;
    EXPECT_TRUE(wantsViewSearch(fit, 0.9, false)) << toString(source);
  }
  for (const ProbabilitySource source :
       {ProbabilitySource::Check, ProbabilitySource::BuiltInExpertCurve}) {
    fit.probabilitySource = source;
    EXPECT_FALSE(wantsViewSearch(fit, 0.9, false)) << toString(source);
    EXPECT_TRUE(wantsViewSearch(fit, 0.9, true)) << toString(source);
  }
}

TEST(TiltAngles, NearestTurnsFirstBothWays) {
  EXPECT_TRUE(tiltAngles(0, 15.0).empty());
  EXPECT_EQ(tiltAngles(2, 15.0), (std::vector<double>{-15.0, 15.0, -30.0, 30.0}));
  EXPECT_EQ(tiltAngles(1, 20.0), (std::vector<double>{-20.0, 20.0}));
}

}  // namespace
}  // namespace clm3d
