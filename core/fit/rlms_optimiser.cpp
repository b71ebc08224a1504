// rlms: regularised landmark mean-shift (Saragih, Lucey and Cohn, "Deformable model fitting by
// regularized landmark mean-shift", IJCV 2011), the fit OpenFace's CLM and CLNF use, here on the
// 3D shape model and the view's discriminative patch experts.
//
// Per step, for each landmark the view's model holds: the expert's response map pi over a
// (2r+1)^2 window around its projected position x_k, sampled in a frame turned with the face's
// in-plane rotation (core/fit/response_map.hpp); the mean-shift of a Gaussian kernel density over
// the window's candidates,
//
//   v_k = sum_y pi_y N(y; x_k, sigma^2 I) (y - x_k) / sum_y pi_y N(y; x_k, sigma^2 I),
//
// turned back into the image; then one Gauss-Newton step of the shape model's pose and shape
// towards x + v, with the shape prior (b_i^2 / variance_i) weighted by the regularisation rho:
//
//   (J' J + rho diag(prior)) dp = J' v - rho diag(prior) p.
//
// (Weighting each landmark by its map's total response was tried and changed nothing measurable
// on LFPW.) The in-plane rotation is faceInPlaneAngle.
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string_view>
#include <vector>

#include "core/fit/detail/optimiser_factories.hpp"
#include "core/fit/optimiser.hpp"
#include "core/fit/response_map.hpp"

namespace clm3d {
namespace {

class RlmsOptimiser final : public Optimiser {
 public:
  explicit RlmsOptimiser(const OptimiserSettings& settings)
      : radius_(std::max(settings.rlmsRadius, 1)),
        sigma_(std::max(settings.rlmsSigma, 0.1)),
        rho_(std::max(settings.rlmsRegularisation, 0.0)) {
    const int side = 2 * radius_ + 1;
    kernel_.resize(side * side);
    for (int dy = -radius_; dy <= radius_; ++dy) {
      for (int dx = -radius_; dx <= radius_; ++dx) {
        kernel_[(dy + radius_) * side + dx + radius_] =
            std::exp(-0.5 * (dx * dx + dy * dy) / (sigma_ * sigma_));
      }
    }
  }

  std::string_view name() const override { return "rlms"; }
  bool usesExperts() const override { return true; }

  void step(const SearchProblem& problem, Eigen::VectorXd& p) override {
    const ShapeProjector& projector = problem.projector();
    const PatchModel& patches = problem.patchModel();
    const int m = projector.landmarkCount();
    const int params = projector.paramCount();
    if (m == 0 || static_cast<int>(patches.experts.size()) != m) return;
    jacobian_.resize(2 * m, params);
    points_.resize(2, m);
    projector.jacobian(p, jacobian_, &points_);
    const double angle = faceInPlaneAngle(projector, p);

    const int size = problem.patchSize() + 2 * radius_;
    shift_.resize(2 * m);
    for (int k = 0; k < m; ++k) {
      sampleRegion(problem.image(), points_.col(k), angle, size, region_);
      expertResponse(region_, patches.experts[static_cast<std::size_t>(k)], problem.patchSize(),
                     response_);
      Eigen::Vector2d weighted = Eigen::Vector2d::Zero();
      double total = 0.0;
      for (int dy = -radius_; dy <= radius_; ++dy) {
        const float* row = response_.ptr<float>(dy + radius_);
        for (int dx = -radius_; dx <= radius_; ++dx) {
          const double pi = row[dx + radius_];
          const double w = pi * kernel_[(dy + radius_) * (2 * radius_ + 1) + dx + radius_];
          weighted += w * Eigen::Vector2d(dx, dy);
          total += w;
        }
      }
      const Eigen::Vector2d local =
          total > 1e-12 ? Eigen::Vector2d(weighted / total) : Eigen::Vector2d::Zero();
      shift_.segment<2>(2 * k) = rotateOffset(local, angle);
    }
    system_.noalias() = jacobian_.transpose() * jacobian_;
    rhs_.noalias() = jacobian_.transpose() * shift_;
    const double floor = 1e-9 * (system_.trace() / params + 1e-300);
    for (int i = 0; i < params; ++i) {
      const double prior = rho_ * problem.prior()[i];
      rhs_[i] -= prior * p[i];
      system_(i, i) += prior + floor;
    }
    ldlt_.compute(system_);
    increment_ = ldlt_.solve(rhs_);
    if (increment_.allFinite()) p += increment_;
  }

 private:
  int radius_;
  double sigma_;
  double rho_;
  Eigen::MatrixXd jacobian_;
  Eigen::Matrix2Xd points_;
  Eigen::VectorXd shift_;
  Eigen::MatrixXd system_;
  Eigen::VectorXd rhs_;
  Eigen::VectorXd increment_;
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
  std::vector<double> kernel_;  // the mean-shift kernel over the window, row-major
  cv::Mat region_;
  cv::Mat response_;
};

}  // namespace

std::unique_ptr<Optimiser> makeRlmsOptimiser(const OptimiserSettings& settings) {
  return std::make_unique<RlmsOptimiser>(settings);
}

}  // namespace clm3d
