#include "core/viz/landmark_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

namespace clm3d {

void drawLandmarks(cv::Mat& image, const LandmarkSet& points, const std::vector<bool>& visible,
                   const Scheme& scheme, const OverlayStyle& style) {
  const int size = std::min(image.cols, image.rows);
  const int radius = std::max(2, static_cast<int>(std::lround(style.scale * size / 120.0)));
  const double fontScale = style.scale * std::max(0.3, size / 900.0);
  constexpr int kShift = 4;  // sub-pixel drawing
  const cv::Scalar black(0, 0, 0, 255);
  for (int i = 0; i < points.size(); ++i) {
    if (!points.has(i)) continue;
    const Eigen::Vector3d p = points.point(i);
    const int region = i < scheme.size() ? scheme.regionOf(i) : -1;
    cv::Scalar colour(0, 255, 255, 255);
    if (region >= 0) {
      const RgbColour c = scheme.regions()[static_cast<std::size_t>(region)].colour;
      colour = cv::Scalar(c.b, c.g, c.r, 255);
    }
    const bool shown = visible.empty() || visible[static_cast<std::size_t>(i)];
    const cv::Point centre(static_cast<int>(std::lround(p.x() * (1 << kShift))),
                           static_cast<int>(std::lround(p.y() * (1 << kShift))));
    cv::circle(image, centre, radius << kShift, black, shown ? cv::FILLED : 3, cv::LINE_AA, kShift);
    cv::circle(image, centre, (radius - 1) << kShift, colour, shown ? cv::FILLED : 1, cv::LINE_AA,
               kShift);
    if (!style.numbers) continue;
    const cv::Point label(static_cast<int>(p.x()) + radius + 1, static_cast<int>(p.y()) - radius);
    const std::string text = std::to_string(i + 1);
    cv::putText(image, text, label, cv::FONT_HERSHEY_SIMPLEX, fontScale, black, 3, cv::LINE_AA);
    cv::putText(image, text, label, cv::FONT_HERSHEY_SIMPLEX, fontScale, colour, 1, cv::LINE_AA);
  }
}

}  // namespace clm3d
