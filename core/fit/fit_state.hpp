// What a fit estimates, the head pose and the shape coefficients b_s, and the flat parameter
// vector the optimisers move: p = [tx, ty, scale, pitch, yaw, roll, b_1 .. b_K]. The depth Tz is
// not a parameter: under a perspective camera it trades almost exactly against the scale, so a
// fit keeps the depth it started from and moves the scale.
#pragma once

#include <Eigen/Core>

#include "core/geometry/pose.hpp"

namespace clm3d {

struct FitState {
  Pose pose;
  Eigen::VectorXd shape;  // b_s, one entry per shape mode
};

enum FitParam : int { kParamTx = 0, kParamTy, kParamScale, kParamPitch, kParamYaw, kParamRoll };
inline constexpr int kPoseParamCount = 6;

// Index of shape coefficient k in the parameter vector.
constexpr int shapeParam(int k) {
  return kPoseParamCount + k;
}

Eigen::VectorXd toParams(const FitState& state);
// Writes p into state, keeping state.pose.translation.z(). p must have 6 + state.shape.size()
// entries; no allocation when state.shape already has the right size.
void fromParams(const Eigen::Ref<const Eigen::VectorXd>& p, FitState& state);

}  // namespace clm3d
