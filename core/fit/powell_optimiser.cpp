// The `powell` optimiser (thesis section 4.2.1): Powell's direction set method with Brent line
// searches on -meanNcc, in unit-step coordinates (core/fit/detail/unit_step_objective.hpp). One
// step() is one Powell iteration: a line search along each direction, then the standard direction
// replacement and a line search along the new direction. The direction set is kept across the
// steps of a fit, so the conjugate directions learnt at one step carry to the next (the templates
// change between steps, but the shape of the objective's valley barely does); it starts again from
// the unit vectors at every beginFit and whenever the number of free parameters changes.
#include <memory>

#include "core/common/error.hpp"
#include "core/fit/detail/direction_set.hpp"
#include "core/fit/detail/optimiser_factories.hpp"
#include "core/fit/detail/unit_step_objective.hpp"

namespace clm3d {
namespace {

class PowellOptimiser final : public Optimiser {
 public:
  explicit PowellOptimiser(const OptimiserSettings& settings) {
    line_.initialStep = 1.0;  // one unit step: about a pixel of point motion
    line_.maxIterations = settings.lineIterations;
    // Brent stops within ~0.02 px: well below the fitter's convergence tolerance (0.1 px).
    line_.absoluteTolerance = 0.01;
    line_.relativeTolerance = 1e-3;
  }

  std::string_view name() const override { return "powell"; }

  void beginFit(const Eigen::Ref<const Eigen::VectorXd>& /*p*/) override { fresh_ = true; }

  void step(const SearchProblem& problem, Eigen::VectorXd& p) override {
    objective_.reset(problem, p);
    const int n = objective_.dimension();
    if (n == 0) return;
    if (fresh_ || directions_.dimension() != n || paramCount_ != problem.paramCount() ||
        active_ != objective_.active()) {
      directions_.reset(n);
      paramCount_ = problem.paramCount();
      active_ = objective_.active();
      fresh_ = false;
    }
    // The templates are patchSize wide: a line search further than that compares them with image
    // content they were not synthesised from.
    line_.maxStep = problem.patchSize();
    y_.setZero(n);
    const double start = objective_(y_);
    auto project = [this](Eigen::VectorXd& y) { objective_.project(y); };
    directions_.iterate(objective_, y_, start, line_, project);
    objective_.toParams(y_, p);
  }

 private:
  LineSearchSettings line_;
  UnitStepObjective objective_;
  DirectionSet directions_;
  std::vector<int> active_;
  int paramCount_ = -1;
  bool fresh_ = true;
  Eigen::VectorXd y_;
};

}  // namespace

std::unique_ptr<Optimiser> makePowellOptimiser(const OptimiserSettings& settings) {
  if (settings.lineIterations < 1) {
    throw InputError("powell: the line search needs at least 1 iteration (lineIterations)");
  }
  return std::make_unique<PowellOptimiser>(settings);
}

}  // namespace clm3d
