// The landmarks the point refiner leaves out follow the refined ones through the 3D shape: a fit
// whose refined points say the face is larger and elsewhere than the search's state gets its
// other points where the model fitted to the refined ones puts them, not where the search left
// them; a fit the refiner did not move keeps every point.
#include "core/track/detail/unrefined_landmarks.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "core/detect/initialisation.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d {
namespace {

// The fixture model with a refiner over landmarks first..last (0-based; its stages are never run
// here: only which landmarks it refines matters).
ClmModel modelRefining(int first, int last) {
  ClmModel model = test::fitTestModel();
  model.refiner.landmarks.resize(static_cast<std::size_t>(last - first + 1));
  std::iota(model.refiner.landmarks.begin(), model.refiner.landmarks.end(), first);
  model.refiner.meanShape = Eigen::Matrix2Xd::Zero(2, last - first + 1);
  model.refiner.stages.resize(1);
  return model;
}

struct MovedFit {
  FitResult fit;
  Eigen::Matrix2Xd moved;  // every landmark of the state the refined points come from
};

// A search's fit of `scene` whose refined landmarks were moved to a face 12% larger, 9 px right
// and 5 px down (as a refiner corrects a search's size and place); the rest are the search's.
MovedFit movedFit(const ClmModel& model, const test::FitScene& scene) {
  const FitState moved = test::perturbState(scene, model, 9.0, 5.0, 0.0, 1.12, 0.0);
  MovedFit out;
  out.fit.state = scene.truth;
  out.fit.points = projectState(model, scene.camera, scene.truth);
  out.moved = projectState(model, scene.camera, moved);
  for (const int landmark : model.refiner.landmarks) {
    out.fit.points.col(landmark) = out.moved.col(landmark);
  }
  out.fit.refined = true;
  return out;
}

TEST(UnrefinedLandmarks, FollowTheRefinedPointsThroughTheShape) {
  const ClmModel model = modelRefining(0, 17);
  const test::FitScene scene = test::makeFitScene(model, 0.0, 0.0);
  MovedFit moved = movedFit(model, scene);
  const Eigen::Matrix2Xd before = moved.fit.points;
  std::vector<bool> unrefined(25, false);
  for (int landmark = 18; landmark < 25; ++landmark) unrefined[landmark] = true;
  // The search left them several pixels from where the refined points put the face.
  ASSERT_GT(test::meanPointError(before, moved.moved, unrefined), 5.0);

  placeUnrefinedLandmarks(model, scene.camera, moved.fit);
  EXPECT_LT(test::meanPointError(moved.fit.points, moved.moved, unrefined), 0.5);
  std::vector<bool> refined(25, false);
  for (int landmark = 0; landmark < 18; ++landmark) refined[landmark] = true;
  EXPECT_EQ(test::meanPointError(moved.fit.points, before, refined), 0.0)
      << "the refined points themselves are reported as refined";
  EXPECT_EQ(moved.fit.state.pose.scale, scene.truth.pose.scale) << "the state stays the search's";
}

TEST(UnrefinedLandmarks, AFitTheRefinerDidNotMoveKeepsItsPoints) {
  const ClmModel model = modelRefining(0, 17);
  const test::FitScene scene = test::makeFitScene(model, 0.0, 0.0);
  MovedFit moved = movedFit(model, scene);
  moved.fit.refined = false;
  const Eigen::Matrix2Xd before = moved.fit.points;
  placeUnrefinedLandmarks(model, scene.camera, moved.fit);
  EXPECT_EQ(test::meanPointError(moved.fit.points, before), 0.0);

  ClmModel unrefining = test::fitTestModel();
  unrefining.refiner = {};
  moved.fit.refined = true;
  placeUnrefinedLandmarks(unrefining, scene.camera, moved.fit);
  EXPECT_EQ(test::meanPointError(moved.fit.points, before), 0.0);
}

TEST(UnrefinedLandmarks, APointInsideTheRefinedOnesKeepsTheSearchs) {
  // mid_eyes (landmark 0), between the refined eyes and brows, is left to the search; the ear
  // lobes beyond them follow the shape.
  const ClmModel model = modelRefining(1, 17);
  const test::FitScene scene = test::makeFitScene(model, 0.0, 0.0);
  MovedFit moved = movedFit(model, scene);
  const Eigen::Matrix2Xd before = moved.fit.points;
  placeUnrefinedLandmarks(model, scene.camera, moved.fit);
  EXPECT_EQ((moved.fit.points.col(0) - before.col(0)).norm(), 0.0);
  EXPECT_LT((moved.fit.points.col(18) - moved.moved.col(18)).norm(), 0.5);
  EXPECT_GT((before.col(18) - moved.moved.col(18)).norm(), 5.0);
}

}  // namespace
}  // namespace clm3d
