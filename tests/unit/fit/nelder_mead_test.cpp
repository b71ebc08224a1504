// The Nelder-Mead simplex: first the pure algorithm of core/fit/detail/simplex.hpp on analytic
// functions (a rotated ill-conditioned quadratic, Rosenbrock's valley, the iteration cap), then the
// `nelder-mead` optimiser through the Fitter on a synthetic render with a known pose and shape
// perturbation.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <numbers>

#include "core/common/error.hpp"
#include "core/fit/detail/simplex.hpp"
#include "core/fit/optimiser.hpp"
#include "tests/unit/fit/optimiser_fit_check.hpp"

namespace clm3d {
namespace {

TEST(NelderMeadSimplex, MinimisesARotatedIllConditionedQuadratic) {
  // Condition number 100, axes rotated 30 degrees, minimum at (1, -2, 0.5).
  Eigen::Matrix3d rotation;
  const double a = std::numbers::pi / 6.0;
  rotation << std::cos(a), -std::sin(a), 0.0, std::sin(a), std::cos(a), 0.0, 0.0, 0.0, 1.0;
  const Eigen::Matrix3d hessian =
      rotation.transpose() * Eigen::Vector3d(1.0, 0.01, 0.2).asDiagonal() * rotation;
  const Eigen::Vector3d centre(1.0, -2.0, 0.5);
  auto f = [&](const Eigen::VectorXd& x) {
    const Eigen::Vector3d d = x - centre;
    return d.dot(hessian * d);
  };
  SimplexSettings settings;
  settings.maxIterations = 2000;
  settings.xTolerance = 1e-8;
  settings.fTolerance = 1e-16;
  NelderMeadSimplex simplex;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
  const double fx = simplex.minimise(f, x, f(x), settings);
  EXPECT_LT(fx, 1e-12);
  EXPECT_LT((x - centre).norm(), 1e-4);
  EXPECT_LT(simplex.iterations(), settings.maxIterations);  // stopped by the tolerances
}

TEST(NelderMeadSimplex, MinimisesTheRosenbrockFunction) {
  auto rosenbrock = [](const Eigen::VectorXd& x) {
    const double a = 1.0 - x[0], b = x[1] - x[0] * x[0];
    return a * a + 100.0 * b * b;
  };
  SimplexSettings settings;
  settings.initialSize = 0.5;
  settings.maxIterations = 1000;
  settings.xTolerance = 1e-9;
  settings.fTolerance = 1e-18;
  NelderMeadSimplex simplex;
  Eigen::VectorXd x(2);
  x << -1.2, 1.0;
  simplex.minimise(rosenbrock, x, rosenbrock(x), settings);
  EXPECT_NEAR(x[0], 1.0, 1e-5);
  EXPECT_NEAR(x[1], 1.0, 1e-5);
  EXPECT_LT(simplex.evaluations(), 400);
}

TEST(NelderMeadSimplex, RespectsTheIterationCapAndNeverReturnsWorseThanTheStart) {
  auto f = [](const Eigen::VectorXd& x) { return x.squaredNorm() + std::sin(3.0 * x[0]); };
  SimplexSettings settings;
  settings.maxIterations = 5;
  NelderMeadSimplex simplex;
  Eigen::VectorXd x(4);
  x << 2.0, -1.0, 0.5, 3.0;
  const double start = f(x);
  const double fx = simplex.minimise(f, x, start, settings);
  EXPECT_EQ(simplex.iterations(), 5);
  EXPECT_LE(fx, start);
  EXPECT_DOUBLE_EQ(fx, f(x));
  // n evaluations for the initial simplex, then at most 2 per iteration unless it shrinks
  // (n more): 4 + 5 (2 + 4) at most.
  EXPECT_LE(simplex.evaluations(), 4 + 5 * 6);
}

TEST(NelderMeadOptimiser, IsRegisteredByName) {
  const auto optimiser = makeOptimiser("nelder-mead");
  EXPECT_EQ(optimiser->name(), "nelder-mead");
}

TEST(NelderMeadOptimiser, OneStepImprovesTheMatchAgainstFixedTemplates) {
  test::expectStepImproves("nelder-mead", {}, 0.5);
}

TEST(NelderMeadOptimiser, RecoversAPoseAndShapePerturbationOfASyntheticRender) {
  const ClmModel& model = test::fitTestModel();
  const test::FitCheck check =
      test::runFitCheck(model, test::makeFitScene(model, 0.0, 0.0), "nelder-mead");
  // Measured: 6.3 -> 0.5 px (inter-ocular 58 px).
  EXPECT_GT(check.startError, 0.09 * check.interOcular);
  EXPECT_LT(check.finalError, 0.3 * check.startError);
  EXPECT_LT(check.finalError, 0.03 * check.interOcular);
}

TEST(NelderMeadOptimiser, HonoursTheIterationSetting) {
  // One simplex iteration per step cannot get far: the same search ends clearly worse.
  OptimiserSettings settings;
  settings.simplexIterations = 1;
  const ClmModel& model = test::fitTestModel();
  const test::FitScene scene = test::makeFitScene(model, 0.0, 0.0);
  const test::FitCheck capped = test::runFitCheck(model, scene, "nelder-mead", settings);
  EXPECT_GT(capped.finalError, 0.5 * capped.startError);
  settings.simplexIterations = -1;
  EXPECT_THROW(makeOptimiser("nelder-mead", settings), InputError);
}

}  // namespace
}  // namespace clm3d
