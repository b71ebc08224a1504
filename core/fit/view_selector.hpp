// Chooses the texture model's view from the current head pitch and yaw (thesis section 3.3), with
// hysteresis: the current view is kept until another view's centre is nearer by more than a
// margin, so a head held near a boundary between two views does not flicker between them.
#pragma once

#include "core/model/clm_model.hpp"

namespace clm3d {

class ViewSelector {
 public:
  ViewSelector(const ClmModel& model, double hysteresisDeg);
  // The view for (pitch, yaw) in degrees given the current view (-1: none yet). Distances are
  // Euclidean in (pitch, yaw) degrees between the pose and the view centres.
  int select(double pitchDeg, double yawDeg, int current) const;

 private:
  const ClmModel* model_;
  double hysteresisDeg_;
};

}  // namespace clm3d
