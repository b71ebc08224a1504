#include "core/synth/detail/angle_warp.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/synth/detail/synth_math.hpp"

namespace clm3d::synth {

AngleWarp::AngleWarp(double low, double high, double fineLow, double fineHigh, double fineStep,
                     double coarseStep, double blend)
    : low_(low), high_(high) {
  constexpr int kSamples = 8192;
  const auto density = [&](double a) {
    const double inside =
        smoothstep(fineLow - blend, fineLow, a) * (1.0 - smoothstep(fineHigh, fineHigh + blend, a));
    return 1.0 / coarseStep + (1.0 / fineStep - 1.0 / coarseStep) * inside;
  };
  cdf_.resize(kSamples + 1);
  cdf_[0] = 0.0;
  const double h = (high - low) / kSamples;
  for (int i = 1; i <= kSamples; ++i) {
    const double a0 = low + h * (i - 1);
    cdf_[static_cast<std::size_t>(i)] =
        cdf_[static_cast<std::size_t>(i - 1)] + 0.5 * h * (density(a0) + density(a0 + h));
  }
  const double total = cdf_.back();
  cells_ = std::max(4, static_cast<int>(std::lround(total)));
  for (double& c : cdf_) c /= total;
}

double AngleWarp::angle(double s) const {
  s = std::clamp(s, 0.0, 1.0);
  const auto it = std::lower_bound(cdf_.begin(), cdf_.end(), s);
  std::size_t i = static_cast<std::size_t>(it - cdf_.begin());
  i = std::clamp<std::size_t>(i, 1, cdf_.size() - 1);
  const double c0 = cdf_[i - 1];
  const double c1 = cdf_[i];
  const double f = c1 > c0 ? (s - c0) / (c1 - c0) : 0.0;
  const double h = (high_ - low_) / static_cast<double>(cdf_.size() - 1);
  const double degreesValue = low_ + h * (static_cast<double>(i - 1) + f);
  return degreesValue * std::numbers::pi / 180.0;
}

}  // namespace clm3d::synth
