// Checks shared by the tests of the derivative-free optimisers (powell, nelder-mead,
// condensation) on the fit fixture (tests/support/fit_fixture.hpp): one optimiser step against
// fixed templates, and the Fitter's whole search from a known pose and shape perturbation of a
// synthetic render, measured by the mean point error against the true landmarks.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/fit/fitter.hpp"
#include "core/fit/optimiser.hpp"
#include "core/fit/search_problem.hpp"
#include "core/fit/working_image.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d::test {

struct FitCheck {
  double startError = 0.0;  // mean point error of the start (pixels, visible landmarks)
  double finalError = 0.0;  // of the fit
  double interOcular = 0.0;
  FitResult result;
};

// The start of the recovery checks: the truth moved by 4 px right, 3 px up, 4 degrees in roll and
// yaw, 4 % in scale and 0.6 SD in every shape mode (about 6 px, 0.11 inter-ocular, of mean point
// error on the frontal render).
inline FitState perturbedStart(const FitScene& scene, const ClmModel& model) {
  return perturbState(scene, model, 4.0, -3.0, 4.0, 1.04, 0.6);
}

// The Fitter's whole search of `scene` with the named optimiser from perturbedStart.
inline FitCheck runFitCheck(const ClmModel& model, const FitScene& scene,
                            const std::string& optimiser, const OptimiserSettings& settings = {}) {
  const FitState start = perturbedStart(scene, model);
  FitSettings fitSettings;
  fitSettings.optimiser = optimiser;
  fitSettings.optimiserSettings = settings;
  Fitter fitter(model, scene.camera, fitSettings);
  FitCheck check;
  check.interOcular = scene.interOcular;
  check.startError = meanPointError(fitter.project(start), scene.truthPoints, scene.visible);
  check.result = fitter.fit(scene.image, start);
  check.finalError = meanPointError(check.result.points, scene.truthPoints, scene.visible);
  return check;
}

// One view at one pyramid level of a fixture render, with the templates synthesised at the truth
// and a start perturbed from it: the objective an optimiser's single step works on.
struct FixedProblem {
  FitScene scene;
  WorkingImage working;
  std::unique_ptr<SearchProblem> problem;
  Eigen::VectorXd truth;
  Eigen::VectorXd start;
};

inline FixedProblem makeFixedProblem(int level, double yawDeg = 0.0) {
  const ClmModel& model = fitTestModel();
  FixedProblem f;
  f.scene = makeFitScene(model, 0.0, yawDeg);
  const Eigen::Matrix2Xd& t = f.scene.truthPoints;
  const double scale = model.views.front().scales.front().patchSize / model.patchRatio /
                       f.scene.interOcular;  // the fitter's working scale
  makeWorkingImage(f.scene.image, t.rowwise().minCoeff().array() - 40.0,
                   t.rowwise().maxCoeff().array() + 40.0, scale, level + 1, f.working);
  f.problem = std::make_unique<SearchProblem>(model.shape, f.scene.camera);
  const int view = model.nearestView(0.0, yawDeg);
  f.problem->configure(model.views[static_cast<std::size_t>(view)].scales[level], f.working, level,
                       true, f.scene.truth.pose.translation.z());
  f.truth = toParams(f.scene.truth);
  f.problem->synthesiseTemplates(f.truth);
  f.start = toParams(perturbState(f.scene, model, 2.0, -1.5, 2.0, 1.02, 0.3));
  f.problem->clamp(f.start);
  return f;
}

// Mean point distance (level pixels) between two parameter vectors under the problem's projector.
inline double levelPointError(const SearchProblem& problem, const Eigen::VectorXd& a,
                              const Eigen::VectorXd& b) {
  Eigen::Matrix2Xd pa(2, problem.landmarkCount()), pb(2, problem.landmarkCount());
  problem.projector().project(a, pa);
  problem.projector().project(b, pb);
  return (pa - pb).colwise().norm().mean();
}

// One step of `optimiser` against templates fixed at the truth: the mean NCC must not drop and
// the points must end nearer the truth.
inline void expectStepImproves(const std::string& optimiser, const OptimiserSettings& settings = {},
                               double errorRatio = 0.7) {
  FixedProblem f = makeFixedProblem(0);
  const auto opt = makeOptimiser(optimiser, settings);
  Eigen::VectorXd p = f.start;
  opt->beginFit(p);
  const double before = f.problem->meanNcc(p);
  opt->step(*f.problem, p);
  f.problem->clamp(p);
  EXPECT_GE(f.problem->meanNcc(p), before) << optimiser;
  const double startError = levelPointError(*f.problem, f.start, f.truth);
  EXPECT_LT(levelPointError(*f.problem, p, f.truth), errorRatio * startError) << optimiser;
}

}  // namespace clm3d::test
