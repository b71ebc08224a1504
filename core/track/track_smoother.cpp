#include "core/track/track_smoother.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

// The exponential smoothing factor of a first-order low-pass with this cutoff over dt seconds.
double smoothingFactor(double cutoffHz, double dt) {
  const double tau = 1.0 / (2.0 * std::numbers::pi * cutoffHz);
  return 1.0 / (1.0 + tau / dt);
}

}  // namespace

void checkSmoothingSettings(const SmoothingSettings& settings) {
  const auto positive = [](double value, const char* name) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw InputError(std::string("smoothing: ") + name + " must be a positive number, not " +
                       std::to_string(value));
    }
  };
  positive(settings.minCutoffHz, "the minimum cutoff");
  positive(settings.derivativeCutoffHz, "the derivative cutoff");
  if (!(settings.beta >= 0.0) || !std::isfinite(settings.beta)) {
    throw InputError("smoothing: beta must be zero or more, not " + std::to_string(settings.beta));
  }
}

PointSmoother::PointSmoother(const SmoothingSettings& settings) : settings_(settings) {
  checkSmoothingSettings(settings_);
}

void PointSmoother::restart() {
  values_.resize(2, 0);
  speeds_.resize(2, 0);
}

void PointSmoother::filter(Eigen::Matrix2Xd& points, double timestamp, double eyeDistance) {
  const double dt = timestamp - lastTime_;
  const bool continues = hasHistory() && values_.cols() == points.cols() && dt > 0.0 &&
                         std::isfinite(dt) && eyeDistance > 0.0 && std::isfinite(eyeDistance);
  if (!continues) {
    values_ = points;
    speeds_ = Eigen::Matrix2Xd::Zero(2, points.cols());
    lastTime_ = timestamp;
    return;
  }
  const double speedAlpha = smoothingFactor(settings_.derivativeCutoffHz, dt);
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const Eigen::Vector2d raw = points.col(i);
    if (!raw.allFinite() || !values_.col(i).allFinite()) {
      values_.col(i) = raw;  // no position: nothing to filter, start afresh when it comes back
      speeds_.col(i).setZero();
      continue;
    }
    const Eigen::Vector2d speed = (raw - values_.col(i)) / dt;
    speeds_.col(i) += speedAlpha * (speed - speeds_.col(i));
    const double cutoff =
        settings_.minCutoffHz + settings_.beta * speeds_.col(i).norm() / eyeDistance;
    values_.col(i) += smoothingFactor(cutoff, dt) * (raw - values_.col(i));
    points.col(i) = values_.col(i);
  }
  lastTime_ = timestamp;
}

}  // namespace clm3d
