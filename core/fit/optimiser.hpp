// The optimisers of the search (thesis chapter 4), one interface so the fitter, the CLI and the
// experiments select them by name: powell, nelder-mead, gauss-newton, fastncc, condensation.
// Each takes one update step of the parameters against the problem's current templates; the
// fitter re-synthesises the templates between steps and tests convergence.
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
};

class Optimiser {
 public:
  virtual ~Optimiser() = default;
  virtual std::string_view name() const = 0;
  // A new image is about to be searched from p (for tracking: the previous frame's result).
  virtual void beginFit(const Eigen::Ref<const Eigen::VectorXd>& p) { (void)p; }
  // One update of p against problem's current templates. The caller clamps p afterwards.
  virtual void step(const SearchProblem& problem, Eigen::VectorXd& p) = 0;
};

// Throws InputError listing the valid names for an unknown one.
std::unique_ptr<Optimiser> makeOptimiser(std::string_view name,
                                         const OptimiserSettings& settings = {});
const std::vector<std::string>& optimiserNames();

}  // namespace clm3d
