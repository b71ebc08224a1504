#include "core/common/logistic_curve.hpp"

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

LogisticCurve fitLogisticCurve(const std::vector<double>& scores, const std::vector<bool>& labels,
                               const LogisticFitSettings& settings) {
  LogisticCurve curve;
  const std::size_t n = std::min(scores.size(), labels.size());
  const auto positives = static_cast<double>(std::count(labels.begin(), labels.begin() + n, true));
  const double negatives = static_cast<double>(n) - positives;
  if (positives == 0 || negatives == 0) return curve;
  const double weightPositive = settings.balanced ? 0.5 * n / positives : 1.0;
  const double weightNegative = settings.balanced ? 0.5 * n / negatives : 1.0;
  // The penalised negative log-likelihood, in a form that stays finite for saturated scores.
  const auto loss = [&](const LogisticCurve& c) {
    double sum = 0.5 * settings.slopeRidge * c.slope * c.slope;
    for (std::size_t i = 0; i < n; ++i) {
      const double z = c.slope * scores[i] + c.offset;
      const double margin = labels[i] ? z : -z;  // -log p(label) = log(1 + exp(-margin))
      const double nll =
          margin > 0.0 ? std::log1p(std::exp(-margin)) : -margin + std::log1p(std::exp(margin));
      sum += (labels[i] ? weightPositive : weightNegative) * nll;
    }
    return sum;
  };
  double current = loss(curve);
  for (int iteration = 0; iteration < settings.maxIterations; ++iteration) {
    double g0 = settings.slopeRidge * curve.slope, g1 = 0.0;
    double h00 = settings.slopeRidge, h01 = 0.0, h11 = 1e-9;
    for (std::size_t i = 0; i < n; ++i) {
      const double p = curve(scores[i]);
      const double weight = labels[i] ? weightPositive : weightNegative;
      const double e = weight * (p - (labels[i] ? 1.0 : 0.0));
      const double w = weight * p * (1.0 - p);
      g0 += e * scores[i];
      g1 += e;
      h00 += w * scores[i] * scores[i];
      h01 += w * scores[i];
      h11 += w;
    }
    const double det = h00 * h11 - h01 * h01;
    if (!(det > 0.0)) break;
    const double d0 = (h11 * g0 - h01 * g1) / det;
    const double d1 = (h00 * g1 - h01 * g0) / det;
    // Newton's step, halved while it does not lower the loss: from slope 1, scores far from 0
    // (log-odds of near-certain probabilities) would otherwise overshoot without bound.
    LogisticCurve next{curve.slope - d0, curve.offset - d1};
    double step = 1.0, nextLoss = loss(next);
    for (int halving = 0; halving < 40 && !(nextLoss <= current); ++halving) {
      step *= 0.5;
      next = {curve.slope - step * d0, curve.offset - step * d1};
      nextLoss = loss(next);
    }
    if (!(nextLoss <= current)) break;
    curve = next;
    current = nextLoss;
    if (step * (std::abs(d0) + std::abs(d1)) < 1e-9) break;
  }
  return curve;
}

}  // namespace clm3d
