// fastncc: Tiddeman's closed-form NCC update (thesis appendix A.4, eq. A.21-A.30), derived afresh
// in docs/fastncc.md. The templates move (inverse formulation): with the concatenated templates f,
// their derivatives D = [D_k J_k] with respect to the template-side increment delta and the
// concatenated image patches g, the NCC of the linearised template with the image,
//
//   E(delta) = (a + b'delta) / sqrt(c + 2 e'delta + delta' M delta),
//   a = f.g/|g|, b = D'g/|g|, c = |f|^2, e = D'f, M = D'D = sum_k J_k' H_k J_k,
//
// is maximised in closed form (maximiseLinearNcc), and the parameters take the opposite step,
// dp = -delta. The shape prior and a small damping enter as extra "template pixels" (zero in the
// image), which keeps the closed form exact: sqrt(w prior_i) (p - delta)_i for the shape and
// sqrt(mu M_ii) delta_i for the damping. Global NCC of the concatenated patches rather than the
// mean of per-landmark NCCs: it has the closed form, equals the mean NCC at delta = 0 (every patch
// has |t_k|^2 = |g_k|^2 = N) and has the same gradient there (D_k' t_k = 0). Without the prior
// the step is gauss-newton's divided by the current NCC. Parameters that move no point stay fixed;
// a step moves no point further than a quarter of the patch size.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string_view>

#include "core/fit/detail/inverse_alignment.hpp"
#include "core/fit/detail/optimiser_factories.hpp"
#include "core/fit/optimiser.hpp"

namespace clm3d {
namespace {

constexpr double kMinKappa = 0.05;        // below: no interior maximum (maximiseLinearNcc)
constexpr double kMinNccForPrior = 0.25;  // floor of the NCC that scales the prior weight

class FastNccOptimiser final : public Optimiser {
 public:
  explicit FastNccOptimiser(const OptimiserSettings& settings)
      : shapePrior_(std::max(settings.shapePrior, 0.0)) {}

  std::string_view name() const override { return "fastncc"; }

  void step(const SearchProblem& problem, Eigen::VectorXd& p) override {
    linear_.linearise(problem, p);
    const int m = linear_.landmarkCount();
    const int params = linear_.paramCount();
    if (m == 0 || params == 0) return;
    const double imageNorm2 = linear_.imageNorm2().sum();
    const double c0 = linear_.templateNorm2().sum();
    if (!(imageNorm2 > 0.0) || !(c0 > 0.0)) return;
    const double inverseImageNorm = 1.0 / std::sqrt(imageNorm2);

    b_.resize(params);
    e_.resize(params);
    system_.resize(params, params);
    linear_.chain(linear_.imageGradient(), b_);
    b_ *= inverseImageNorm;
    linear_.chain(linear_.templateGradientDotTemplate(), e_);
    const double a = linear_.cross().sum() * inverseImageNorm;
    double c = c0;
    system_ = linear_.hessian();

    // The prior as virtual template pixels sqrt(w prior_i) (p_i - delta_i): to first order they
    // lower E by E w / (2c) |p - delta|^2_prior, so with c = m N, w = lambda / E makes the cost in
    // units of the SSE N sum_k (1 - NCC_k) the same as gauss-newton's lambda/2 |p + dp|^2_prior.
    const double ncc = a / std::sqrt(c0);
    const double weight =
        shapePrior_ * c0 / (double(m) * problem.patchPixels()) / std::max(ncc, kMinNccForPrior);
    const double floor = 1e-12 * (system_.trace() / params + 1e-300);
    for (int i = 0; i < params; ++i) {
      const double prior = weight * problem.prior()[i];
      c += prior * p[i] * p[i];
      e_[i] -= prior * p[i];
      system_(i, i) += kDamping * system_(i, i) + prior + floor;
    }
    linear_.pinFixed(system_, b_, &e_);
    ldlt_.compute(system_);
    maximiseLinearNcc(a, b_, c, e_, ldlt_, u_, w_, delta_, kMinKappa);
    if (!delta_.allFinite()) return;
    delta_ = -delta_;  // the template moved by delta: the image-side parameters move by -delta
    linear_.applyLimitedStep(p, delta_, kMaxStepPatchFraction * problem.patchSize());
  }

 private:
  double shapePrior_;
  InverseLinearisation linear_;
  Eigen::VectorXd b_, e_, u_, w_, delta_;
  Eigen::MatrixXd system_;
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
};

}  // namespace

std::unique_ptr<Optimiser> makeFastNccOptimiser(const OptimiserSettings& settings) {
  return std::make_unique<FastNccOptimiser>(settings);
}

}  // namespace clm3d
