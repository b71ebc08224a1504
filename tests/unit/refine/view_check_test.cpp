// A view's own check (core/refine/view_check.hpp): it reads the view's visible points in the
// frame of the mean shape seen from the view, a mirrored view reads its fit flipped into its
// source's frame (so that a face turned left and its mirror image turned right give one
// reading), and a fit's finishing gives it the check's probability.
#include "core/refine/view_check.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "core/refine/descent_check.hpp"
#include "core/refine/refined_fit.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d {
namespace {

int viewAtYaw(const ClmModel& model, double yawDeg) {
  for (std::size_t v = 0; v < model.views.size(); ++v) {
    if (model.views[v].yawDeg == yawDeg) return static_cast<int>(v);
  }
  return -1;
}

double relativeDifference(const Eigen::VectorXf& a, const Eigen::VectorXf& b) {
  return (a - b).norm() / (0.5 * (a.norm() + b.norm()));
}

TEST(ViewCheck, TheLayoutIsTheViewsVisiblePointsOnABoxOfSizeOne) {
  const ClmModel& model = test::fitTestModel();
  const int side = viewAtYaw(model, -30.0);
  const int mirrored = viewAtYaw(model, 30.0);
  ASSERT_GE(side, 0);
  ASSERT_GE(mirrored, 0);
  ASSERT_FALSE(model.views[static_cast<std::size_t>(side)].mirrored);
  ASSERT_TRUE(model.views[static_cast<std::size_t>(mirrored)].mirrored);
  const ViewCheck layout = viewCheckLayout(model, side);
  const std::vector<bool>& visible = model.views[static_cast<std::size_t>(side)].visible;
  ASSERT_EQ(static_cast<std::size_t>(layout.meanShape.cols()), layout.landmarks.size());
  EXPECT_EQ(layout.landmarks.size(),
            static_cast<std::size_t>(std::count(visible.begin(), visible.end(), true)));
  for (const int landmark : layout.landmarks)
    EXPECT_TRUE(visible[static_cast<std::size_t>(landmark)]);
  const Eigen::Vector2d low = layout.meanShape.rowwise().minCoeff();
  const Eigen::Vector2d high = layout.meanShape.rowwise().maxCoeff();
  EXPECT_NEAR((high - low).prod(), 1.0, 1e-9);
  EXPECT_NEAR((high + low).norm(), 0.0, 1e-9);
  EXPECT_EQ(layout.classifier.window, kViewCheckWindow);
  EXPECT_TRUE(layout.empty());  // nothing learnt yet
  EXPECT_THROW(viewCheckLayout(model, mirrored), Error);
}

// The head at -30 degrees read in the -30 view, and the same image flipped left-right (the head
// at +30, its points mirrored) read in the mirrored +30 view, give the same features up to the
// crop's rounding; moving the points by a sixth of the face changes them twenty times more.
TEST(ViewCheck, AMirroredViewReadsItsFitFlippedIntoItsSourcesFrame) {
  const ClmModel& model = test::fitTestModel();
  const int side = viewAtYaw(model, -30.0);
  const int mirrored = viewAtYaw(model, 30.0);
  const test::FitScene scene = test::makeFitScene(model, 0.0, -30.0, test::kHeldOutHead, 60.0);
  const ViewCheck layout = viewCheckLayout(model, side);
  const Eigen::VectorXf source =
      viewCheckFeatures(model, side, layout, scene.image, scene.truthPoints);
  ASSERT_EQ(source.size(),
            static_cast<Eigen::Index>(layout.landmarks.size()) * kDescentFeaturesPerPoint);

  cv::Mat flipped;
  cv::flip(scene.image, flipped, 1);
  const Scheme scheme = model.scheme();
  Eigen::Matrix2Xd mirroredPoints(2, scene.truthPoints.cols());
  for (int i = 0; i < scheme.size(); ++i) {
    const Eigen::Vector2d p = scene.truthPoints.col(scheme.mirrorOf(i));
    mirroredPoints.col(i) = Eigen::Vector2d(flipped.cols - 1 - p.x(), p.y());
  }
  const Eigen::VectorXf throughMirror =
      viewCheckFeatures(model, mirrored, layout, flipped, mirroredPoints);
  ASSERT_EQ(throughMirror.size(), source.size());
  const double mirrorDifference = relativeDifference(source, throughMirror);
  EXPECT_LT(mirrorDifference, 0.1);  // 0.052 measured

  const double face = std::sqrt(
      (scene.truthPoints.rowwise().maxCoeff() - scene.truthPoints.rowwise().minCoeff()).prod());
  Eigen::Matrix2Xd moved = scene.truthPoints;
  moved.row(0).array() += face / 6.0;
  const double movedDifference =
      relativeDifference(source, viewCheckFeatures(model, side, layout, scene.image, moved));
  EXPECT_GT(movedDifference, 10.0 * mirrorDifference)  // 1.17 measured
      << "mirror " << mirrorDifference << ", moved " << movedDifference;

  // Read in the mirrored view without the flip (the source's landmarks at the fit's own
  // positions), the features are those of another face.
  EXPECT_GT(
      relativeDifference(source, viewCheckFeatures(model, side, layout, flipped, mirroredPoints)),
      5.0 * mirrorDifference);
}

TEST(ViewCheck, PointsThatCannotBeReadGiveNoFeaturesAndNoProbability) {
  const ClmModel& model = test::fitTestModel();
  const int side = viewAtYaw(model, -30.0);
  const test::FitScene scene = test::makeFitScene(model, 0.0, -30.0, 0, 60.0);
  const ViewCheck layout = viewCheckLayout(model, side);
  Eigen::Matrix2Xd points = scene.truthPoints;
  points(0, layout.landmarks.front()) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(viewCheckFeatures(model, side, layout, scene.image, points).size(), 0);
  const Eigen::Matrix2Xd collapsed = Eigen::Matrix2Xd::Constant(2, points.cols(), 50.0);
  EXPECT_EQ(viewCheckFeatures(model, side, layout, scene.image, collapsed).size(), 0);
  // The fixture model has no view checks: no probability.
  EXPECT_TRUE(std::isnan(viewCheckProbability(model, side, scene.image, scene.truthPoints)));
}

// A check whose score is its bias alone gives every readable fit the bias's probability, and
// refineFit puts it in FitResult::viewProbability; in a view the refiner did not learn it becomes
// the fit's probability.
TEST(ViewCheck, AFinishedFitCarriesItsViewsCheck) {
  ClmModel model = test::fitTestModel();
  const int side = viewAtYaw(model, -30.0);
  const int mirrored = viewAtYaw(model, 30.0);
  ViewCheck check = viewCheckLayout(model, side);
  const auto d = static_cast<Eigen::Index>(check.landmarks.size()) * kDescentFeaturesPerPoint;
  check.classifier.featureMean = Eigen::VectorXf::Zero(d);
  check.classifier.weights = Eigen::VectorXf::Zero(d);
  check.classifier.bias = 1.5;
  model.views[static_cast<std::size_t>(side)].check = check;
  model.views[static_cast<std::size_t>(mirrored)] =
      mirrorView(model.views[static_cast<std::size_t>(side)], model.scheme());
  model.validate();
  const test::FitScene scene = test::makeFitScene(model, 0.0, -30.0, 0, 60.0);
  const double expected = 1.0 / (1.0 + std::exp(-1.5));
  FitResult fit;
  fit.view = mirrored;
  fit.points = scene.truthPoints;
  fit.probability = 0.25;
  refineFit(model, scene.image, fit);
  EXPECT_NEAR(fit.viewProbability, expected, 1e-9);
  EXPECT_EQ(fit.probability, 0.25) << "a model without a refiner keeps the search's probability";
  const int frontal = viewAtYaw(model, 0.0);
  FitResult unchecked;
  unchecked.view = frontal;
  unchecked.points = scene.truthPoints;
  refineFit(model, scene.image, unchecked);
  EXPECT_TRUE(std::isnan(unchecked.viewProbability));
}

}  // namespace
}  // namespace clm3d
