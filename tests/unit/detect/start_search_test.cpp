// fitFromBestStart: a start outside the search's capture range is recovered by the grid of moved
// starts (one of which lands near the face), the most confident fit is the one returned, and with
// no grid it is the plain search; with a threshold, the grid runs only when the start's own fit
// is below it.
#include "core/detect/start_search.hpp"

#include <gtest/gtest.h>

#include "core/detect/initialisation.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d {
namespace {

double errorOf(const FitResult& fit, const test::FitScene& scene) {
  return test::meanPointError(fit.points, scene.truthPoints) / scene.interOcular;
}

// The cascade's profile box (not mirrored: a face turned to the image's left) around the scene's
// face: a square 1.3 times the truth's points' larger side.
FaceBox profileBoxAround(const test::FitScene& scene) {
  const Eigen::Vector2d low = scene.truthPoints.rowwise().minCoeff();
  const Eigen::Vector2d high = scene.truthPoints.rowwise().maxCoeff();
  const double side = 1.3 * (high - low).maxCoeff();
  const Eigen::Vector2d centre = 0.5 * (low + high);
  FaceBox profile;
  profile.box = cv::Rect2d(centre.x() - 0.5 * side, centre.y() - 0.5 * side, side, side);
  profile.profile = true;
  return profile;
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

// Profile boxes placed again: with BoxPlacement::TurnedFace the face loop searches only the profile
// boxes, each from its second placement (where real turned faces sit in such a box);
// fitFromDetections does so when nothing else was accepted, and keeps the more probable fit.
TEST(FaceSearch, ProfileBoxesArePlacedAgainWhenNoFitIsAccepted) {
  const ClmModel& model = test::fitTestModel();
  const test::FitScene scene = test::makeFitScene(model, 0.0, -45.0);
  Fitter fitter(model, scene.camera);
  const FaceBox profile = profileBoxAround(scene);
  FaceBox frontal = profile;
  frontal.profile = false;
  FaceBox dlibSide = profile;
  dlibSide.detector = DetectorKind::DlibHog;
  EXPECT_FALSE(turnedFaceCalibration(frontal).has_value());
  EXPECT_FALSE(turnedFaceCalibration(dlibSide).has_value());
  const std::optional<BoxCalibration> turned = turnedFaceCalibration(profile);
  ASSERT_TRUE(turned.has_value());
  const FitResult first = fitter.fit(scene.image, stateFromBox(model, scene.camera, profile));
  const FitResult second =
      fitter.fit(scene.image, stateFromBox(model, scene.camera, profile, *turned));
  ASSERT_NE(first.probability, second.probability) << "the two placements fit alike";

  FaceSearch search;
  search.maxFaces = 3;
  search.placement = BoxPlacement::TurnedFace;
  int tried = 0, searches = 0;
  const FitResult placed = fitFromBestFace(fitter, model, scene.image, {frontal, profile, dlibSide},
                                           search, &tried, &searches);
  EXPECT_EQ(tried, 2) << "the frontal box passed over, the profile box's fit kept";
  EXPECT_EQ(searches, 1) << "only the cascade's profile box";
  EXPECT_EQ(placed.probability, second.probability);
  EXPECT_THROW(fitFromBestFace(fitter, model, scene.image, {frontal}, search), InputError);

  // fitFromDetections: nothing is accepted, so the profile box is placed again and the more
  // probable fit kept; without turnedPlacements, or with the first fit accepted, it is not.
  FaceDetector detector;
  FaceSearch rejecting;
  rejecting.accepted = [](const FitResult&) { return false; };
  rejecting.turnedPlacements = true;
  const auto both = fitFromDetections(fitter, model, scene.image, detector, {profile}, rejecting);
  ASSERT_TRUE(both.has_value());
  EXPECT_EQ(both->probability, std::max(first.probability, second.probability));
  rejecting.turnedPlacements = false;
  const auto once = fitFromDetections(fitter, model, scene.image, detector, {profile}, rejecting);
  ASSERT_TRUE(once.has_value());
  EXPECT_EQ(once->probability, first.probability);
  FaceSearch accepting;
  accepting.accepted = [](const FitResult&) { return true; };
  accepting.turnedPlacements = true;
  const auto kept = fitFromDetections(fitter, model, scene.image, detector, {profile}, accepting);
  ASSERT_TRUE(kept.has_value());
  EXPECT_EQ(kept->probability, first.probability);
}

// A profile box's start is searched from its own grid (FaceSearch::profileSteps), a frontal box's
// from the common one; -1 leaves profile boxes on the common grid.
TEST(FaceSearch, AProfileBoxsStartIsSearchedFromItsOwnGrid) {
  const ClmModel& model = test::fitTestModel();
  const test::FitScene scene = test::makeFitScene(model, 0.0, -45.0);
  Fitter fitter(model, scene.camera);
  FaceBox profile = profileBoxAround(scene);
  FaceBox frontal = profile;
  frontal.profile = false;
  FaceSearch search;
  search.starts = StartSearchSettings{1, 0.1, {}, 0.0};  // the whole grid, always
  search.profileSteps = 2;
  const auto searchesFor = [&](const FaceBox& box, const FaceSearch& how) {
    int searches = 0;
    fitFromBestFace(fitter, model, scene.image, {box}, how, nullptr, &searches);
    return searches;
  };
  EXPECT_EQ(searchesFor(profile, search), 25);
  EXPECT_EQ(searchesFor(frontal, search), 9);
  search.profileSteps = -1;
  EXPECT_EQ(searchesFor(profile, search), 9);
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
