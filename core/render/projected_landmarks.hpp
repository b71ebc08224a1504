// A mesh's 3D landmarks projected into one of its renders, each tested against the render's depth
// (the thesis's hidden-point removal): what clm3d render writes with --out-landmarks and draws
// with --overlay, and what the demo's training-view renders show. The result owns its data.
#pragma once

#include <vector>

#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/scheme/landmark_set.hpp"

namespace clm3d {

struct ProjectedLandmarks {
  LandmarkSet points;         // 2D image pixels; missing where the 3D set has no point
  std::vector<bool> visible;  // per landmark; false for missing ones
  std::vector<int> hidden;    // indices of the present landmarks the render hides, increasing
};

// `model` (3D, model coordinates) projected with the pose and camera `render` was drawn with.
ProjectedLandmarks projectLandmarks(const LandmarkSet& model, const RenderResult& render,
                                    const Pose& pose, const Camera& camera);

// The projected points with the hidden ones set missing (clm3d render --hidden-missing).
LandmarkSet visiblePointsOnly(const ProjectedLandmarks& projected);

}  // namespace clm3d
