#include "ui/track/compared_points.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace clm3d::ui {

const TrackRow* comparedRow(const TrackTable& compared, int frame) {
  const auto index = static_cast<std::size_t>(std::max(frame, 0));
  if (index < compared.rows.size() && compared.rows[index].frame == frame)
    return &compared.rows[index];
  for (const TrackRow& row : compared.rows) {
    if (row.frame == frame) return &row;
  }
  return nullptr;
}

cv::Mat withComparedPoints(const cv::Mat& image, const TrackTable& compared, int frame) {
  const TrackRow* row = comparedRow(compared, frame);
  if (!row || image.empty() || !row->points.array().isFinite().any()) return image;
  cv::Mat drawn = image.clone();
  // Sized to the frame so the marks read the same at 360x288 and at 1920x1080.
  const int size = std::max(7, std::min(drawn.cols, drawn.rows) / 45);
  const int thickness = std::max(1, size / 7);
  const cv::Scalar magenta(255, 0, 255, 255);
  for (int i = 0; i < row->points.cols(); ++i) {
    if (!row->points.col(i).allFinite()) continue;
    const cv::Point at(static_cast<int>(std::lround(row->points(0, i))),
                       static_cast<int>(std::lround(row->points(1, i))));
    cv::drawMarker(drawn, at, magenta, cv::MARKER_DIAMOND, size, thickness, cv::LINE_AA);
  }
  return drawn;
}

}  // namespace clm3d::ui
