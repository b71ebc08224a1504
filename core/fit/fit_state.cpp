#include "core/fit/fit_state.hpp"

#include "core/common/error.hpp"

namespace clm3d {

Eigen::VectorXd toParams(const FitState& state) {
  Eigen::VectorXd p(kPoseParamCount + state.shape.size());
  p[kParamTx] = state.pose.translation.x();
  p[kParamTy] = state.pose.translation.y();
  p[kParamScale] = state.pose.scale;
  p[kParamPitch] = state.pose.pitch;
  p[kParamYaw] = state.pose.yaw;
  p[kParamRoll] = state.pose.roll;
  p.tail(state.shape.size()) = state.shape;
  return p;
}

void fromParams(const Eigen::Ref<const Eigen::VectorXd>& p, FitState& state) {
  if (p.size() < kPoseParamCount) throw Error("fit: a parameter vector needs the 6 pose entries");
  state.pose.translation.x() = p[kParamTx];
  state.pose.translation.y() = p[kParamTy];
  state.pose.scale = p[kParamScale];
  state.pose.pitch = p[kParamPitch];
  state.pose.yaw = p[kParamYaw];
  state.pose.roll = p[kParamRoll];
  state.shape = p.tail(p.size() - kPoseParamCount);
}

}  // namespace clm3d
