// The `nelder-mead` optimiser: the downhill simplex of the original CLM (Cristinacce and Cootes;
// thesis section 4.2), kept as the baseline the thesis compares against. Minimises -meanNcc in
// unit-step coordinates (core/fit/detail/unit_step_objective.hpp) from a fresh simplex of size 2
// unit steps around the current parameters at every step: the templates change between steps, so
// the old simplex's values would be stale, and its shape is not worth keeping the way Powell's
// directions are.
#include <memory>

#include "core/common/error.hpp"
#include "core/fit/detail/optimiser_factories.hpp"
#include "core/fit/detail/simplex.hpp"
#include "core/fit/detail/unit_step_objective.hpp"

namespace clm3d {
namespace {

class NelderMeadOptimiser final : public Optimiser {
 public:
  explicit NelderMeadOptimiser(const OptimiserSettings& settings)
      : iterations_(settings.simplexIterations) {
    simplex_.initialSize = 2.0;  // unit steps: the vertices start ~2 px from the current points
    // Stop once every vertex is within 0.01 px of the best and the mean NCCs agree to 1e-6.
    simplex_.xTolerance = 0.01;
    simplex_.fTolerance = 1e-6;
  }

  std::string_view name() const override { return "nelder-mead"; }

  void step(const SearchProblem& problem, Eigen::VectorXd& p) override {
    objective_.reset(problem, p);
    const int n = objective_.dimension();
    if (n == 0) return;
    simplex_.maxIterations = iterations_ > 0 ? iterations_ : 20 * n;
    y_.setZero(n);
    const double start = objective_(y_);
    nelderMead_.minimise(objective_, y_, start, simplex_);
    objective_.toParams(y_, p);
  }

 private:
  int iterations_;
  SimplexSettings simplex_;
  UnitStepObjective objective_;
  NelderMeadSimplex nelderMead_;
  Eigen::VectorXd y_;
};

}  // namespace

std::unique_ptr<Optimiser> makeNelderMeadOptimiser(const OptimiserSettings& settings) {
  if (settings.simplexIterations < 0) {
    throw InputError("nelder-mead: simplexIterations must be >= 0 (0 = 20 x parameter count)");
  }
  return std::make_unique<NelderMeadOptimiser>(settings);
}

}  // namespace clm3d
