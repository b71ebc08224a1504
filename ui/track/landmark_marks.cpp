#include "ui/track/landmark_marks.hpp"

#include <cmath>

namespace clm3d::ui {

std::vector<LandmarkMark> landmarkMarks(const TrackRow* tracked, const Eigen::Matrix2Xd& shown,
                                        double threshold) {
  if (tracked == nullptr) return {};
  const auto n = static_cast<std::size_t>(shown.cols());
  std::vector<LandmarkMark> marks(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (k < tracked->visibility.size()) {
      marks[k].hidden = tracked->visibility[k] == Visibility::Hidden;
    }
    const auto column = static_cast<Eigen::Index>(k);
    const bool moved = column >= tracked->points.cols() ||
                       !((shown.col(column) - tracked->points.col(column)).norm() <= 0.5);
    if (k < tracked->landmarkConfidence.size() && !moved) {
      const double confidence = tracked->landmarkConfidence[k];
      marks[k].lowConfidence = std::isfinite(confidence) && confidence < threshold;
    }
  }
  return marks;
}

}  // namespace clm3d::ui
