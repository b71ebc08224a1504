#include "core/render/projected_landmarks.hpp"

#include "core/geometry/projection.hpp"

namespace clm3d {

ProjectedLandmarks projectLandmarks(const LandmarkSet& model, const RenderResult& render,
                                    const Pose& pose, const Camera& camera) {
  ProjectedLandmarks projected{LandmarkSet(model.size(), 2),
                               std::vector<bool>(static_cast<std::size_t>(model.size()), false),
                               {}};
  for (int i = 0; i < model.size(); ++i) {
    if (!model.has(i)) continue;
    const Eigen::Vector3d point = model.point(i);
    projected.points.set(i, Eigen::Vector2d(projectPoint(point, pose, camera)));
    const bool visible = render.isVisible(point);
    projected.visible[static_cast<std::size_t>(i)] = visible;
    if (!visible) projected.hidden.push_back(i);
  }
  return projected;
}

LandmarkSet visiblePointsOnly(const ProjectedLandmarks& projected) {
  LandmarkSet points = projected.points;
  for (int i = 0; i < points.size(); ++i) {
    if (!projected.visible[static_cast<std::size_t>(i)]) points.setMissing(i);
  }
  return points;
}

}  // namespace clm3d
