// The optimisers of the search (thesis chapter 4), one interface so the fitter, the CLI and the
// experiments select them by name: powell, nelder-mead, gauss-newton, fastncc, condensation (the
// thesis's five, on synthetic templates) and rlms (regularised landmark mean-shift on the
// discriminative experts' response maps). Each takes one update step of the parameters; the
// fitter re-synthesises the templates between steps (for those that use them) and tests
// convergence.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/fit/search_problem.hpp"

namespace clm3d {

struct OptimiserSettings {
  std::uint64_t seed = 1;     // condensation's random stream
  int particles = 25;         // condensation: samples per step (the thesis's 25 seeds)
  double spread = 1.0;        // condensation: dynamics SD in unit steps (ShapeProjector::unitSteps)
  int lineIterations = 12;    // powell: Brent iterations per line search
  int simplexIterations = 0;  // nelder-mead: iterations per step (0 = 20 x parameter count)
  double shapePrior = 1.0;    // gauss-newton and fastncc: weight of the shape prior (0 = none)
  // rlms: search window radius (level pixels), kernel SD of the mean-shift (level pixels) and
  // weight of the shape prior in squared level pixels (Saragih et al.'s regularisation r).
  int rlmsRadius = 4;
  double rlmsSigma = 1.5;
  double rlmsRegularisation = 1.0;

  bool operator==(const OptimiserSettings&) const = default;
};

class Optimiser {
 public:
  virtual ~Optimiser() = default;
  virtual std::string_view name() const = 0;
  // A new image is about to be searched from p (for tracking: the previous frame's result).
  virtual void beginFit(const Eigen::Ref<const Eigen::VectorXd>& p) { (void)p; }
  // One update of p against problem's current templates. The caller clamps p afterwards.
  virtual void step(const SearchProblem& problem, Eigen::VectorXd& p) = 0;
  // True for optimisers that match the view's patch experts, not synthetic templates: the fitter
  // then skips template synthesis and needs a model with experts.
  virtual bool usesExperts() const { return false; }
};

// Throws InputError listing the valid names for an unknown one.
std::unique_ptr<Optimiser> makeOptimiser(std::string_view name,
                                         const OptimiserSettings& settings = {});
const std::vector<std::string>& optimiserNames();

struct ClmModel;
// The name that chooses by the model (the default of fit and track): rlms for a model whose
// point refiner carries a check and whose views all have patch experts (a model trained with
// annotated photos, where rlms with the refiner was measured best on real faces:
// docs/real-faces.md), fastncc for the others (the thesis's models, trained on renders).
inline constexpr std::string_view kAutoOptimiser = "auto";
// `name`, or for kAutoOptimiser the optimiser it chooses for `model`.
std::string resolveOptimiser(std::string_view name, const ClmModel& model);
// kAutoOptimiser and then optimiserNames(): every name a user may give.
const std::vector<std::string>& optimiserChoices();

}  // namespace clm3d
