#include "core/common/decile_progress.hpp"

#include <algorithm>
#include <cmath>

namespace clm3d {

DecileProgress::DecileProgress(std::function<void(int, std::string_view)> report, bool reportStart)
    : report_(std::move(report)), lastDecile_(reportStart ? -1 : 0) {}

void DecileProgress::operator()(double fraction, std::string_view stage) {
  if (!std::isfinite(fraction)) return;
  const int decile = std::clamp(static_cast<int>(fraction * 10.0 + 1e-9), 0, 10);
  std::lock_guard lock(mutex_);
  if (decile <= lastDecile_) return;
  lastDecile_ = decile;
  report_(decile * 10, stage);
}

ProgressCallback DecileProgress::callback() {
  return [this](double fraction, std::string_view stage) { (*this)(fraction, stage); };
}

}  // namespace clm3d
