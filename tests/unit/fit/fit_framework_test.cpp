// Tests of the fitting framework every optimiser relies on: the projector's analytic Jacobian
// against finite differences, the working image's pixel mapping, view selection with hysteresis,
// the search problem's templates and NCC, and the test fixture's truth.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"
#include "core/fit/fitter.hpp"
#include "core/fit/search_problem.hpp"
#include "core/fit/shape_projector.hpp"
#include "core/fit/view_selector.hpp"
#include "core/fit/working_image.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d {
namespace {

using test::fitTestModel;
using test::makeFitScene;

TEST(ShapeProjector, JacobianMatchesFiniteDifferences) {
  for (const ClmModel* model : {&fitTestModel(), &test::fitTestModel2D()}) {
    const test::FitScene scene = makeFitScene(*model, 10.0, -20.0);
    ShapeProjector projector(model->shape, scene.camera);
    projector.setDepth(scene.truth.pose.translation.z());
    WorkingImage working;
    working.gain = {0.8, 0.75};
    working.offset = {-12.0, 7.5};
    projector.setLevel(working, 1);
    Eigen::VectorXd p = toParams(scene.truth);
    p[kParamRoll] = 0.2;
    if (model->shape.modeCount() > 1)
      p[shapeParam(1)] += 0.5 * std::sqrt(model->shape.variances[1]);
    const int m = projector.landmarkCount();
    Eigen::MatrixXd analytic(2 * m, projector.paramCount());
    Eigen::Matrix2Xd points(2, m);
    projector.jacobian(p, analytic, &points);
    Eigen::Matrix2Xd projected(2, m);
    projector.project(p, projected);
    EXPECT_LT((points - projected).cwiseAbs().maxCoeff(), 1e-9);
    for (int k = 0; k < projector.paramCount(); ++k) {
      const double h = 1e-6 * std::max(1.0, std::abs(p[k]));
      Eigen::VectorXd plus = p, minus = p;
      plus[k] += h;
      minus[k] -= h;
      Eigen::Matrix2Xd a(2, m), b(2, m);
      projector.project(plus, a);
      projector.project(minus, b);
      Eigen::Matrix2Xd numeric = (a - b) / (2.0 * h);
      if (projector.planar() && (k == kParamPitch || k == kParamYaw)) numeric.setZero();
      const Eigen::VectorXd flat = Eigen::Map<const Eigen::VectorXd>(numeric.data(), 2 * m);
      EXPECT_LT((analytic.col(k) - flat).cwiseAbs().maxCoeff(), 1e-4 * (1.0 + flat.norm()))
          << "parameter " << k;
    }
  }
}

TEST(ShapeProjector, InputPixelsMatchProjectPoints) {
  const test::FitScene scene = makeFitScene(fitTestModel(), 0.0, 25.0);
  ShapeProjector projector(fitTestModel().shape, scene.camera);
  projector.setDepth(scene.truth.pose.translation.z());
  Eigen::Matrix2Xd points(2, projector.landmarkCount());
  projector.project(toParams(scene.truth), points);
  const Eigen::Matrix2Xd expected =
      projectPoints(fitTestModel().shape.shape(scene.truth.shape), scene.truth.pose, scene.camera);
  EXPECT_LT((points - expected).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(ShapeProjector, ClampKeepsShapeWithinLimitsAndPlanarPoseFlat) {
  const ClmModel& model = test::fitTestModel2D();
  ShapeProjector projector(model.shape, Camera::fromVerticalFov(320, 240, 40.0));
  Eigen::VectorXd p = Eigen::VectorXd::Zero(projector.paramCount());
  p[kParamScale] = -1.0;
  p[kParamYaw] = 0.3;
  p[shapeParam(0)] = 1e6;
  projector.clamp(p);
  EXPECT_GT(p[kParamScale], 0.0);
  EXPECT_EQ(p[kParamYaw], 0.0);
  EXPECT_NEAR(p[shapeParam(0)], model.shape.limitSd * std::sqrt(model.shape.variances[0]), 1e-9);
  EXPECT_EQ(projector.unitSteps(p)[kParamYaw], 0.0);
}

TEST(WorkingImage, MapsInputPixelsToEveryLevel) {
  cv::Mat input(240, 320, CV_8UC3, cv::Scalar(0, 0, 0));
  const Eigen::Vector2d blob(201.0, 117.0);
  cv::circle(input, cv::Point(201, 117), 6, cv::Scalar(255, 255, 255), cv::FILLED);
  WorkingImage working;
  makeWorkingImage(input, {150.0, 80.0}, {260.0, 170.0}, 0.7, 3, working);
  ASSERT_EQ(working.levels.size(), 3u);
  for (int level = 0; level < 3; ++level) {
    const cv::Mat& image = working.levels[static_cast<std::size_t>(level)];
    const cv::Moments m = cv::moments(image);
    const Eigen::Vector2d centroid(m.m10 / m.m00, m.m01 / m.m00);
    EXPECT_LT((centroid - working.toLevel(blob, level)).norm(), 0.15) << "level " << level;
    EXPECT_LT((working.fromLevel(working.toLevel(blob, level), level) - blob).norm(), 1e-9);
  }
  EXPECT_THROW(makeWorkingImage(cv::Mat(), {0, 0}, {1, 1}, 1.0, 1, working), InputError);
  EXPECT_THROW(makeWorkingImage(input, {0, 0}, {10, 10}, 0.0, 1, working), InputError);
}

TEST(ViewSelector, NearestViewWithHysteresis) {
  const ClmModel& model = fitTestModel();  // yaw -30, 0, +30
  const ViewSelector selector(model, 5.0);
  const int frontal = model.nearestView(0, 0);
  const int right = model.nearestView(0, 30);
  EXPECT_EQ(selector.select(0, 10, -1), frontal);
  EXPECT_EQ(selector.select(0, 17, frontal), frontal);  // past the boundary, within the margin
  EXPECT_EQ(selector.select(0, 21, frontal), right);
  EXPECT_EQ(selector.select(0, 13, right), right);
  EXPECT_EQ(selector.select(0, 9, right), frontal);
}

TEST(FitFixture, TruthStateProjectsNearTheTrueLandmarks) {
  const test::FitScene scene = makeFitScene(fitTestModel(), 0.0, 0.0);
  ShapeProjector projector(fitTestModel().shape, scene.camera);
  projector.setDepth(scene.truth.pose.translation.z());
  Eigen::Matrix2Xd points(2, projector.landmarkCount());
  projector.project(toParams(scene.truth), points);
  EXPECT_LT(test::meanPointError(points, scene.truthPoints), 0.04 * scene.interOcular);
  EXPECT_NEAR(scene.interOcular, 60.0, 3.0);
}

TEST(SearchProblem, TemplatesMatchTheImageBestAtTheTruth) {
  const ClmModel& model = fitTestModel();
  const test::FitScene scene = makeFitScene(model, 0.0, 0.0);
  WorkingImage working;
  const Eigen::Matrix2Xd& t = scene.truthPoints;
  makeWorkingImage(scene.image, t.rowwise().minCoeff().array() - 40.0,
                   t.rowwise().maxCoeff().array() + 40.0, 50.0 / scene.interOcular, 2, working);
  SearchProblem problem(model.shape, scene.camera);
  const int view = model.nearestView(0, 0);
  problem.configure(model.views[static_cast<std::size_t>(view)].scales[0], working, 0, true,
                    scene.truth.pose.translation.z());
  const Eigen::VectorXd truth = toParams(scene.truth);
  problem.synthesiseTemplates(truth);
  const double atTruth = problem.meanNcc(truth);
  EXPECT_GT(atTruth, 0.6);
  for (int k = 0; k < problem.landmarkCount(); ++k) {
    EXPECT_NEAR(problem.templ(k).squaredNorm() / problem.patchPixels(), 1.0, 1e-3);
  }
  Eigen::VectorXd shifted = truth;
  shifted[kParamTx] += 3.0 * problem.projector().unitSteps(truth)[kParamTx];
  EXPECT_LT(problem.meanNcc(shifted), atTruth - 0.05);
}

TEST(Fitter, RejectsBadSettingsImagesAndStarts) {
  const ClmModel& model = fitTestModel();
  const Camera camera = Camera::fromVerticalFov(320, 240, 40.0);
  FitSettings settings;
  settings.scales = 5;
  EXPECT_THROW(Fitter(model, camera, settings), InputError);
  settings = {};
  settings.optimiser = "no-such-optimiser";
  EXPECT_THROW(Fitter(model, camera, settings), InputError);
}

}  // namespace
}  // namespace clm3d
