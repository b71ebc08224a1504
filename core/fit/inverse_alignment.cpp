#include "core/fit/detail/inverse_alignment.hpp"

#include <algorithm>
#include <cmath>

namespace clm3d {

void patchGradient(const float* patch, int n, float* gx, float* gy) {
  const int pixels = n * n;
  if (n < 2) {
    std::fill(gx, gx + pixels, 0.0f);
    std::fill(gy, gy + pixels, 0.0f);
    return;
  }
  // Along x, row by row.
  for (int r = 0; r < n; ++r) {
    const float* v = patch + r * n;
    float* d = gx + r * n;
    if (n == 2) {
      d[0] = d[1] = v[1] - v[0];
      continue;
    }
    d[0] = 0.5f * (-3.0f * v[0] + 4.0f * v[1] - v[2]);
    d[n - 1] = 0.5f * (3.0f * v[n - 1] - 4.0f * v[n - 2] + v[n - 3]);
    d[1] = 0.5f * (v[2] - v[0]);
    d[n - 2] = 0.5f * (v[n - 1] - v[n - 3]);
    for (int c = 2; c < n - 2; ++c) {
      d[c] = 0.25f * (v[c + 1] - v[c - 1]) + 0.125f * (v[c + 2] - v[c - 2]);
    }
  }
  // Along y, whole rows at a time (the same cases by row index).
  for (int r = 0; r < n; ++r) {
    float* d = gy + r * n;
    const auto row = [&](int i) { return patch + i * n; };
    if (n == 2) {
      for (int c = 0; c < n; ++c) d[c] = patch[n + c] - patch[c];
    } else if (r == 0 || r == n - 1) {
      // Second-order one-sided: (-3 v0 + 4 v1 - v2) / 2, mirrored at the far border.
      const float sign = r == 0 ? 1.0f : -1.0f;
      const float* v0 = row(r);
      const float* v1 = row(r == 0 ? 1 : n - 2);
      const float* v2 = row(r == 0 ? 2 : n - 3);
      for (int c = 0; c < n; ++c) d[c] = sign * 0.5f * (-3.0f * v0[c] + 4.0f * v1[c] - v2[c]);
    } else if (r == 1 || r == n - 2) {
      const float* lo = row(r - 1);
      const float* hi = row(r + 1);
      for (int c = 0; c < n; ++c) d[c] = 0.5f * (hi[c] - lo[c]);
    } else {
      const float* lo2 = row(r - 2);
      const float* lo1 = row(r - 1);
      const float* hi1 = row(r + 1);
      const float* hi2 = row(r + 2);
      for (int c = 0; c < n; ++c) {
        d[c] = 0.25f * (hi1[c] - lo1[c]) + 0.125f * (hi2[c] - lo2[c]);
      }
    }
  }
}

LinearNccSolution maximiseLinearNcc(double a, const Eigen::Ref<const Eigen::VectorXd>& b, double c,
                                    const Eigen::Ref<const Eigen::VectorXd>& e,
                                    const Eigen::LDLT<Eigen::MatrixXd>& factor, Eigen::VectorXd& u,
                                    Eigen::VectorXd& w, Eigen::VectorXd& delta, double minKappa) {
  u.resize(b.size());
  w.resize(b.size());
  delta.resize(b.size());
  u = factor.solve(b);
  w = factor.solve(e);
  const double beta = b.dot(u);   // b' M^-1 b
  const double gamma = b.dot(w);  // b' M^-1 e
  const double eps = e.dot(w);    // e' M^-1 e
  // c - e'M^-1 e = |f_perp|^2, the squared norm of the part of f that D cannot explain (>= 0 up to
  // rounding); a - b'M^-1 e = g . f_perp.
  const double residual = std::max(c - eps, 0.0);
  const double root = std::sqrt(residual);
  const double numerator = a - gamma;

  LinearNccSolution solution;
  solution.current = c > 0.0 ? a / std::sqrt(c) : 0.0;
  solution.kappa = root > 0.0 ? numerator / root : 0.0;
  minKappa = std::max(minKappa, 1e-6);
  if (root > 0.0 && numerator > minKappa * root) {
    solution.lambda = residual / numerator;
    solution.interior = true;
  } else {
    // No interior maximum: move towards the supremum (lambda -> infinity) by a bounded amount.
    const double scale = std::max(root, 1e-9 * std::sqrt(std::max(c, 0.0)));
    solution.lambda = scale / minKappa;
  }
  delta = solution.lambda * u - w;
  // E(delta) from the same scalars: Q = c - eps + lambda^2 beta, L = a - gamma + lambda beta.
  const double q = residual + solution.lambda * solution.lambda * beta;
  const double l = numerator + solution.lambda * beta;
  solution.predicted = q > 0.0 ? l / std::sqrt(q) : 0.0;
  return solution;
}

bool InverseLinearisation::refresh(const SearchProblem& problem) {
  const int m = problem.landmarkCount();
  const int n = problem.patchSize();
  if (problem_ == &problem && version_ == problem.templateVersion() && patchSize_ == n &&
      templNorm2_.size() == m) {
    return false;
  }
  problem_ = &problem;
  version_ = problem.templateVersion();
  patchSize_ = n;
  const int pixels = n * n;
  gradients_.resize(pixels, 2 * m);
  hessians_.resize(3, m);
  templGrad_.resize(2 * m);
  templNorm2_.resize(m);
  gx_.resize(pixels);
  gy_.resize(pixels);

  for (int k = 0; k < m; ++k) {
    // Keep the Refs alive: .array() of a temporary would dangle.
    const auto texture = problem.synthetic(k);
    const auto alphaRef = problem.mask(k);
    const auto templRef = problem.templ(k);
    const auto s = texture.array();
    const auto alpha = alphaRef.array();
    const auto t = templRef.array();
    auto dx = gradients_.col(2 * k).array();
    auto dy = gradients_.col(2 * k + 1).array();
    const auto gx = gx_.array();
    const auto gy = gy_.array();

    // t = normalise(alpha .* S): the standard deviation of alpha .* S, and S's own mean and spread.
    // Float sums of a few hundred values of order one are exact enough here and vectorise.
    const double mean = (alpha * s).sum() / pixels;
    const double variance = (alpha * s).square().sum() / pixels - mean * mean;
    const double tt = t.square().sum();
    const double meanS = s.sum() / pixels;
    const double spreadS = s.square().sum() - pixels * meanS * meanS;  // |S - mean S|^2
    templNorm2_[k] = tt;
    if (!(variance > 1e-12) || !(tt > 0.0) || !(spreadS > 1e-12) || !std::isfinite(variance)) {
      dx.setZero();
      dy.setZero();
      hessians_.col(k).setZero();
      templGrad_.segment<2>(2 * k).setZero();
      continue;
    }

    // The image side is normalise(alpha .* normalise(raw(x + s + u))), the template side
    // normalise(alpha .* S) with S the reconstruction of a normalised patch. So moving the
    // texture, S(u + s), differentiates as: grad S; the inner normalisation (centre it, remove its
    // component along S - mean S); the fixed mask; the outer normalisation (centre, divide by the
    // standard deviation of alpha .* S, remove the component along t). Hence t_k' D_k = 0.
    patchGradient(texture.data(), n, gx_.data(), gy_.data());
    const float meanX = gx.sum() / pixels;
    const float meanY = gy.sum() / pixels;
    const float alongX = static_cast<float>(((s - meanS) * gx).sum() / spreadS);
    const float alongY = static_cast<float>(((s - meanS) * gy).sum() / spreadS);
    const float centre = static_cast<float>(meanS);
    dx = alpha * (gx - meanX - (s - centre) * alongX);
    dy = alpha * (gy - meanY - (s - centre) * alongY);
    const float meanVx = dx.sum() / pixels;
    const float meanVy = dy.sum() / pixels;
    const float projectX = static_cast<float>((dx * t).sum() / tt);  // t is zero-mean
    const float projectY = static_cast<float>((dy * t).sum() / tt);
    const float inverseSd = static_cast<float>(1.0 / std::sqrt(variance));
    dx = (dx - meanVx - projectX * t) * inverseSd;
    dy = (dy - meanVy - projectY * t) * inverseSd;
    hessians_.col(k) << (dx.square()).sum(), (dx * dy).sum(), (dy.square()).sum();
    templGrad_[2 * k] = (dx * t).sum();
    templGrad_[2 * k + 1] = (dy * t).sum();
  }
  return true;
}

Eigen::Matrix2d InverseLinearisation::landmarkHessian(int k) const {
  Eigen::Matrix2d h;
  h << hessians_(0, k), hessians_(1, k), hessians_(1, k), hessians_(2, k);
  return h;
}

void InverseLinearisation::linearise(const SearchProblem& problem,
                                     const Eigen::Ref<const Eigen::VectorXd>& p) {
  refresh(problem);
  const int m = problem.landmarkCount();
  const int params = problem.paramCount();
  const int pixels = problem.patchPixels();
  jacobian_.resize(2 * m, params);
  points_.resize(2, m);
  patches_.resize(pixels, m);
  imageGrad_.resize(2 * m);
  cross_.resize(m);
  imageNorm2_.resize(m);
  weighted_.resize(2 * m, params);
  hessian_.resize(params, params);
  fixed_.resize(params);
  displacement_.resize(2 * m);

  problem.projector().jacobian(p, jacobian_, &points_);
  for (int k = 0; k < m; ++k) {
    auto g = patches_.col(k);
    problem.sampleMasked(k, points_.col(k), g);
    imageGrad_[2 * k] = static_cast<double>(gradients_.col(2 * k).dot(g));
    imageGrad_[2 * k + 1] = static_cast<double>(gradients_.col(2 * k + 1).dot(g));
    cross_[k] = static_cast<double>(problem.templ(k).dot(g));
    imageNorm2_[k] = static_cast<double>(g.squaredNorm());
    weighted_.middleRows<2>(2 * k).noalias() = landmarkHessian(k) * jacobian_.middleRows<2>(2 * k);
  }
  hessian_.noalias() = jacobian_.transpose() * weighted_;
  const bool planar = problem.projector().planar();
  for (int i = 0; i < params; ++i) {
    const bool still = m == 0 || jacobian_.col(i).cwiseAbs().maxCoeff() == 0.0;
    fixed_[i] = static_cast<char>(still || (planar && (i == kParamPitch || i == kParamYaw)));
  }
}

void InverseLinearisation::chain(const Eigen::Ref<const Eigen::VectorXd>& v,
                                 Eigen::Ref<Eigen::VectorXd> out) const {
  out.noalias() = jacobian_.transpose() * v;
}

double InverseLinearisation::maxDisplacement(const Eigen::Ref<const Eigen::VectorXd>& dp) {
  displacement_.noalias() = jacobian_ * dp;
  double largest = 0.0;
  for (Eigen::Index k = 0; k + 1 < displacement_.size(); k += 2) {
    largest = std::max(largest, std::hypot(displacement_[k], displacement_[k + 1]));
  }
  return largest;
}

void InverseLinearisation::pinFixed(Eigen::MatrixXd& system, Eigen::VectorXd& rhs,
                                    Eigen::VectorXd* other) const {
  for (int i = 0; i < paramCount(); ++i) {
    if (!fixed(i)) continue;
    system.row(i).setZero();
    system.col(i).setZero();
    system(i, i) = 1.0;
    rhs[i] = 0.0;
    if (other != nullptr) (*other)[i] = 0.0;
  }
}

void InverseLinearisation::applyLimitedStep(Eigen::VectorXd& p, Eigen::VectorXd& dp,
                                            double maxPixels) {
  const double moved = maxDisplacement(dp);
  if (moved > maxPixels) dp *= maxPixels / moved;
  p += dp;
}

}  // namespace clm3d
