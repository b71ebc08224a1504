#include "core/fit/view_selector.hpp"

#include <cmath>

namespace clm3d {

ViewSelector::ViewSelector(const ClmModel& model, double hysteresisDeg)
    : model_(&model), hysteresisDeg_(hysteresisDeg) {}

int ViewSelector::select(double pitchDeg, double yawDeg, int current) const {
  const int nearest = model_->nearestView(pitchDeg, yawDeg);
  const int count = static_cast<int>(model_->views.size());
  if (current < 0 || current >= count || nearest == current || nearest < 0) return nearest;
  const auto distance = [&](int v) {
    return std::hypot(model_->views[v].pitchDeg - pitchDeg, model_->views[v].yawDeg - yawDeg);
  };
  return distance(current) <= distance(nearest) + hysteresisDeg_ ? current : nearest;
}

}  // namespace clm3d
