// gauss-newton: inverse additive Gauss-Newton on the sum of squared differences between the masked,
// normalised templates and image patches (thesis appendix A.3, eq. A.14-A.20).
//
// Per landmark the template t_k moves by a translation s_k: t_k(s) ~ t_k + D_k s with D_k the
// derivative of the normalised template (core/fit/detail/inverse_alignment.hpp). Sampling the image
// at x_k + dx matches the template best where the template, shifted by -dx, matches the patch at
// x_k: so the template-side increment s found by least squares maps to the image-side increment dx
// = -s (the inverse additive sign; checked by the tests). With the points' Jacobian J_k, dx_k = J_k
// dp, and the shape prior, one step minimises
//
//   1/2 sum_k |t_k - D_k J_k dp - g_k|^2 + lambda/2 |p + dp|^2_prior,
//
// i.e. solves
//
//   (sum_k J_k' H_k J_k + lambda diag(prior) + damping) dp
//       = sum_k J_k' D_k' (t_k - g_k) - lambda diag(prior) p.
//
// Units: the data term, half the thesis's SSE (eq. A.14) of the normalised patches, is
// N sum_k (1 - NCC_k) (N pixels per patch), and OptimiserSettings::shapePrior = lambda weighs the
// squared Mahalanobis distance of the shape, |b|^2_prior = sum_i b_i^2 / variance_i: lambda = 1 is
// the maximum a posteriori estimate if the normalised patch pixels carried independent unit
// variance noise. Real residuals are smaller and correlated, so 1 is a mild prior that mostly
// steadies modes the visible points hardly constrain; tens to hundreds hold the shape noticeably
// nearer the mean. fastncc uses the same units. H_k = D_k' D_k is computed once per template
// synthesis; per step only the image patches, 2-vectors per landmark and P x P algebra remain.
// The damping adds kDamping * H_ii to the diagonal, and a step moves no point by more than a
// quarter of the patch size. Parameters that move no point (pitch and yaw of the planar model)
// stay fixed.
#include <algorithm>
#include <memory>
#include <string_view>

#include "core/fit/detail/inverse_alignment.hpp"
#include "core/fit/detail/optimiser_factories.hpp"
#include "core/fit/optimiser.hpp"

namespace clm3d {
namespace {

class GaussNewtonOptimiser final : public Optimiser {
 public:
  explicit GaussNewtonOptimiser(const OptimiserSettings& settings)
      : shapePrior_(std::max(settings.shapePrior, 0.0)) {}

  std::string_view name() const override { return "gauss-newton"; }

  void step(const SearchProblem& problem, Eigen::VectorXd& p) override {
    linear_.linearise(problem, p);
    const int m = linear_.landmarkCount();
    const int params = linear_.paramCount();
    if (m == 0 || params == 0) return;
    residual_.resize(2 * m);
    rhs_.resize(params);
    increment_.resize(params);
    system_.resize(params, params);
    residual_ = linear_.templateGradientDotTemplate() - linear_.imageGradient();
    linear_.chain(residual_, rhs_);
    system_ = linear_.hessian();
    const double floor = 1e-12 * (system_.trace() / params + 1e-300);
    for (int i = 0; i < params; ++i) {
      const double prior = shapePrior_ * problem.prior()[i];
      rhs_[i] -= prior * p[i];
      system_(i, i) += kDamping * system_(i, i) + prior + floor;
    }
    linear_.pinFixed(system_, rhs_);
    ldlt_.compute(system_);
    increment_ = ldlt_.solve(rhs_);
    if (!increment_.allFinite()) return;
    linear_.applyLimitedStep(p, increment_, kMaxStepPatchFraction * problem.patchSize());
  }

 private:
  double shapePrior_;
  InverseLinearisation linear_;
  Eigen::VectorXd residual_;
  Eigen::VectorXd rhs_;
  Eigen::VectorXd increment_;
  Eigen::MatrixXd system_;
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
};

}  // namespace

std::unique_ptr<Optimiser> makeGaussNewtonOptimiser(const OptimiserSettings& settings) {
  return std::make_unique<GaussNewtonOptimiser>(settings);
}

}  // namespace clm3d
