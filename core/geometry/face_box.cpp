#include "core/geometry/face_box.hpp"

#include <cmath>
#include <limits>

namespace clm3d {

double faceBoxSize(const Eigen::Matrix2Xd& points) {
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    if (!points.col(i).allFinite()) continue;
    low = low.cwiseMin(points.col(i));
    high = high.cwiseMax(points.col(i));
  }
  if (!(high.x() > low.x()) || !(high.y() > low.y())) return 0.0;
  return std::sqrt((high.x() - low.x()) * (high.y() - low.y()));
}

}  // namespace clm3d
