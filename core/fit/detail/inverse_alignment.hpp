// The template-side ("inverse") linearisation shared by the gauss-newton and fastncc optimisers
// (thesis appendix A.3, A.4): per landmark, the derivative of the masked, normalised template with
// respect to a translation of its texture, computed once per template synthesis with the 5-tap
// kernel of eq. 4.5; per step, the image patches at the current points and the per-landmark sums
// that chain through 2x2 blocks and ShapeProjector::jacobian into P x P systems; and the
// closed-form maximiser of the linearised NCC derived in docs/fastncc.md. One implementation so
// that both optimisers and their finite-difference tests use the same derivatives. Nothing
// allocates after the first call with given sizes (the optimisers run it every iteration).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cstdint>

#include "core/fit/search_problem.hpp"

namespace clm3d {

// d/dx (along columns) and d/dy (along rows) of a row-major n x n patch into gx and gy (n * n
// values each). Interior: the kernel of thesis eq. 4.5 applied as a correlation, halved,
// [-1/8, -1/4, 0, 1/4, 1/8] (the thesis's [-1/4, -1/2, 0, 1/2, 1/4] answers 2 on a unit ramp);
// one pixel from the border the central difference, on the border the second-order one-sided
// difference (-3 v0 + 4 v1 - v2) / 2 (n = 2: the plain difference). So the gradient is exact on
// quadratics everywhere (n >= 3) and no sample outside the patch is invented (clamping indices
// instead would halve the gradient on the border rows).
void patchGradient(const float* patch, int n, float* gx, float* gy);

// What maximiseLinearNcc found.
struct LinearNccSolution {
  double lambda = 0.0;     // delta = lambda * u - w
  double kappa = 0.0;      // cosine between g and the part of f that D cannot explain
  bool interior = false;   // delta is the maximum; false: the bounded step along M^-1 b
  double predicted = 0.0;  // E(delta)
  double current = 0.0;    // E(0) = a / sqrt(c)
};

// Maximises the linearised NCC E(d) = (a + b.d) / sqrt(c + 2 e.d + d'Md) (docs/fastncc.md), given
// `factor` = the LDLT of M (symmetric positive definite): delta = lambda u - w with u = M^-1 b,
// w = M^-1 e and lambda = (c - e.w) / (a - b.w). When a - b.w is not clearly positive
// (kappa < minKappa) E has no interior maximum (the stationary point is its minimum, or lies at
// infinity); then lambda is capped at sqrt(c - e.w) / minKappa, a step towards the supremum that
// joins the interior solution continuously. u, w and delta are outputs (resized to P).
LinearNccSolution maximiseLinearNcc(double a, const Eigen::Ref<const Eigen::VectorXd>& b, double c,
                                    const Eigen::Ref<const Eigen::VectorXd>& e,
                                    const Eigen::LDLT<Eigen::MatrixXd>& factor, Eigen::VectorXd& u,
                                    Eigen::VectorXd& w, Eigen::VectorXd& delta,
                                    double minKappa = 0.05);

// The Gauss-Newton steps on this linearisation (gauss-newton, fastncc) add this share of each
// diagonal entry of the normal matrix (Levenberg damping, scale-free across pose and shape
// units), and move no point further than this share of the patch size: the linearisation of a
// template is not worth more than a few of its pixels.
inline constexpr double kDamping = 0.01;
inline constexpr double kMaxStepPatchFraction = 0.25;

// Per-template derivatives and per-step sums of one SearchProblem. Notation (docs/fastncc.md):
// t_k the masked, normalised template of landmark k, g_k the masked, normalised image patch at
// the current point x_k, D_k (N x 2) the derivative of t_k when its texture is sampled at
// u + s instead of u (s a 2D shift, level pixels; the same convention as moving the image point by
// s), H_k = D_k' D_k, J_k the two rows of ShapeProjector::jacobian of landmark k.
class InverseLinearisation {
 public:
  // Recomputes D_k, H_k, D_k' t_k and |t_k|^2 when the problem's templates changed since the last
  // call (another problem, a new templateVersion or other sizes). Returns true if it recomputed.
  bool refresh(const SearchProblem& problem);
  // refresh(problem), then at p: the Jacobian and points, the image patches g_k, and the sums
  // D_k' g_k, t_k . g_k, |g_k|^2, the Gauss-Newton matrix M = sum_k J_k' H_k J_k and which
  // parameters do not move any point (their Jacobian column is zero: pitch and yaw of the planar
  // model); those must stay fixed.
  void linearise(const SearchProblem& problem, const Eigen::Ref<const Eigen::VectorXd>& p);

  int landmarkCount() const { return static_cast<int>(templNorm2_.size()); }
  int paramCount() const { return static_cast<int>(jacobian_.cols()); }

  // N x 2m: columns 2k, 2k+1 are dt_k/ds_x, dt_k/ds_y.
  const Eigen::MatrixXf& templateGradients() const { return gradients_; }
  // 3 x m: (H_k(0,0), H_k(0,1), H_k(1,1)).
  const Eigen::Matrix<double, 3, Eigen::Dynamic>& landmarkHessians() const { return hessians_; }
  Eigen::Matrix2d landmarkHessian(int k) const;
  const Eigen::VectorXd& templateGradientDotTemplate() const { return templGrad_; }  // 2m: D_k' t_k
  const Eigen::VectorXd& templateNorm2() const { return templNorm2_; }               // m: |t_k|^2

  const Eigen::MatrixXd& jacobian() const { return jacobian_; }        // 2m x P
  const Eigen::Matrix2Xd& points() const { return points_; }           // 2 x m, level pixels
  const Eigen::MatrixXf& imagePatches() const { return patches_; }     // N x m: g_k
  const Eigen::VectorXd& imageGradient() const { return imageGrad_; }  // 2m: D_k' g_k
  const Eigen::VectorXd& cross() const { return cross_; }              // m: t_k . g_k
  const Eigen::VectorXd& imageNorm2() const { return imageNorm2_; }    // m: |g_k|^2
  const Eigen::MatrixXd& hessian() const { return hessian_; }          // P x P: sum J_k' H_k J_k
  bool fixed(int param) const { return fixed_[param] != 0; }

  // J' v for a 2m-vector v (stacked per-landmark 2-vectors) into out (P).
  void chain(const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> out) const;
  // Largest point displacement |J_k dp| over the landmarks (level pixels).
  double maxDisplacement(const Eigen::Ref<const Eigen::VectorXd>& dp);
  // Pins the fixed parameters of a P x P system: their rows and columns become the identity's and
  // their right-hand-side entries (in `rhs` and, when given, `other`) zero, so they do not move.
  void pinFixed(Eigen::MatrixXd& system, Eigen::VectorXd& rhs,
                Eigen::VectorXd* other = nullptr) const;
  // p += dp, with dp first shortened so that no point moves more than maxPixels (the template's
  // linearisation is not worth more than a few of its pixels).
  void applyLimitedStep(Eigen::VectorXd& p, Eigen::VectorXd& dp, double maxPixels);

 private:
  const SearchProblem* problem_ = nullptr;
  std::uint64_t version_ = 0;
  int patchSize_ = -1;

  Eigen::MatrixXf gradients_;
  Eigen::Matrix<double, 3, Eigen::Dynamic> hessians_;
  Eigen::VectorXd templGrad_;
  Eigen::VectorXd templNorm2_;
  Eigen::VectorXf gx_, gy_;

  Eigen::MatrixXd jacobian_;
  Eigen::Matrix2Xd points_;
  Eigen::MatrixXf patches_;
  Eigen::VectorXd imageGrad_;
  Eigen::VectorXd cross_;
  Eigen::VectorXd imageNorm2_;
  Eigen::MatrixXd weighted_;  // 2m x P: H_k J_k
  Eigen::MatrixXd hessian_;
  Eigen::Matrix<char, Eigen::Dynamic, 1> fixed_;
  Eigen::VectorXd displacement_;
};

}  // namespace clm3d
