#include "core/common/logistic_curve.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace clm3d {

double LogisticCurve::operator()(double score) const {
  return 1.0 / (1.0 + std::exp(-(slope * score + offset)));
}

double logOdds(double probability) {
  const double p = std::clamp(probability, 1e-12, 1.0 - 1e-12);
  return std::log(p / (1.0 - p));
}

namespace {

// log(1 + exp(-margin)), finite for any margin: -log p(label) when margin is the signed score.
double negativeLogLikelihood(double margin) {
  return margin > 0.0 ? std::log1p(std::exp(-margin)) : -margin + std::log1p(std::exp(margin));
}

}  // namespace

Eigen::VectorXd fitLogisticRegression(const Eigen::MatrixXd& inputs,
                                      const std::vector<bool>& labels,
                                      const Eigen::VectorXd& penalties,
                                      const Eigen::VectorXd& start, bool balanced,
                                      int maxIterations) {
  const Eigen::Index n =
      std::min<Eigen::Index>(inputs.rows(), static_cast<Eigen::Index>(labels.size()));
  Eigen::VectorXd w = start;
  const auto positives = static_cast<double>(
      std::count(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(n), true));
  const double negatives = static_cast<double>(n) - positives;
  if (positives == 0 || negatives == 0) return w;
  const double weightPositive = balanced ? 0.5 * static_cast<double>(n) / positives : 1.0;
  const double weightNegative = balanced ? 0.5 * static_cast<double>(n) / negatives : 1.0;
  Eigen::VectorXd target(n), weight(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const bool label = labels[static_cast<std::size_t>(i)];
    target(i) = label ? 1.0 : 0.0;
    weight(i) = label ? weightPositive : weightNegative;
  }
  const auto rows = inputs.topRows(n);
  const auto loss = [&](const Eigen::VectorXd& v) {
    const Eigen::VectorXd z = rows * v;
    double sum = 0.5 * v.dot(penalties.cwiseProduct(v));
    for (Eigen::Index i = 0; i < n; ++i)
      sum += weight(i) * negativeLogLikelihood(target(i) > 0.5 ? z(i) : -z(i));
    return sum;
  };
  double current = loss(w);
  for (int iteration = 0; iteration < maxIterations; ++iteration) {
    const Eigen::VectorXd z = rows * w;
    const Eigen::VectorXd p = (1.0 + (-z.array()).exp()).inverse().matrix();
    const Eigen::VectorXd error = weight.cwiseProduct(p - target);
    const Eigen::VectorXd curvature = weight.array() * p.array() * (1.0 - p.array());
    const Eigen::VectorXd gradient = rows.transpose() * error + penalties.cwiseProduct(w);
    Eigen::MatrixXd hessian = rows.transpose() * curvature.asDiagonal() * rows;
    hessian.diagonal() += penalties + Eigen::VectorXd::Constant(w.size(), 1e-9);
    const Eigen::VectorXd step = hessian.ldlt().solve(gradient);
    if (!step.allFinite()) break;
    // Newton's step, halved while it does not lower the loss: from slope 1, scores far from 0
    // (log-odds of near-certain probabilities) would otherwise overshoot without bound.
    double scale = 1.0;
    Eigen::VectorXd next = w - step;
    double nextLoss = loss(next);
    for (int halving = 0; halving < 40 && !(nextLoss <= current); ++halving) {
      scale *= 0.5;
      next = w - scale * step;
      nextLoss = loss(next);
    }
    if (!(nextLoss <= current)) break;
    w = next;
    current = nextLoss;
    if (scale * step.lpNorm<1>() < 1e-9) break;
  }
  return w;
}

LogisticCurve fitLogisticCurve(const std::vector<double>& scores, const std::vector<bool>& labels,
                               const LogisticFitSettings& settings) {
  const std::size_t n = std::min(scores.size(), labels.size());
  Eigen::MatrixXd inputs(static_cast<Eigen::Index>(n), 2);
  for (std::size_t i = 0; i < n; ++i) inputs.row(static_cast<Eigen::Index>(i)) << scores[i], 1.0;
  const Eigen::VectorXd w = fitLogisticRegression(
      inputs, std::vector<bool>(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(n)),
      Eigen::Vector2d(settings.slopeRidge, 0.0), Eigen::Vector2d(1.0, 0.0), settings.balanced,
      settings.maxIterations);
  return {w(0), w(1)};
}

}  // namespace clm3d
