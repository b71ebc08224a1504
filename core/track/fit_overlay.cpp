#include "core/track/fit_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "core/viz/landmark_overlay.hpp"

namespace clm3d {
namespace {

// A template in normalised units (zero mean, unit SD) as an 8-bit grey patch.
cv::Mat templateImage(const Eigen::VectorXf& values, int size) {
  cv::Mat patch(size, size, CV_8UC1);
  for (int r = 0; r < size; ++r) {
    for (int c = 0; c < size; ++c) {
      const float v = values[r * size + c];
      patch.at<unsigned char>(r, c) =
          static_cast<unsigned char>(std::clamp(128.0f + 48.0f * v, 0.0f, 255.0f));
    }
  }
  return patch;
}

void pastePatch(cv::Mat& bgr, const cv::Mat& grey, const Eigen::Vector2d& centre,
                double pixelSize) {
  const int side = std::max(2, static_cast<int>(std::lround(grey.cols * pixelSize)));
  cv::Mat scaled;
  cv::resize(grey, scaled, cv::Size(side, side), 0, 0, cv::INTER_LINEAR);
  cv::cvtColor(scaled, scaled, cv::COLOR_GRAY2BGR);
  const int x0 = static_cast<int>(std::lround(centre.x() - (side - 1) / 2.0));
  const int y0 = static_cast<int>(std::lround(centre.y() - (side - 1) / 2.0));
  const cv::Rect target = cv::Rect(x0, y0, side, side) & cv::Rect(0, 0, bgr.cols, bgr.rows);
  if (target.area() <= 0) return;
  scaled(cv::Rect(target.x - x0, target.y - y0, target.width, target.height)).copyTo(bgr(target));
}

}  // namespace

void drawFitOverlay(cv::Mat& bgr, const TrackStep& step, const Fitter& fitter, const Scheme& scheme,
                    const FitOverlayOptions& options) {
  if (step.fit && options.patches) {
    const FitResult& fit = *step.fit;
    const auto& templates = fitter.lastTemplates();
    std::size_t entry = 0;
    for (std::size_t i = 0; i < fit.modelled.size() && entry < templates.size(); ++i) {
      if (!fit.modelled[i]) continue;
      const Eigen::VectorXf& values = templates[entry++];
      const int size = static_cast<int>(std::lround(std::sqrt(static_cast<double>(values.size()))));
      pastePatch(bgr, templateImage(values, size), fit.points.col(static_cast<Eigen::Index>(i)),
                 fitter.lastTemplatePixelSize());
    }
  }
  if (step.fit && options.landmarks) {
    const FitResult& fit = *step.fit;
    LandmarkSet points(static_cast<int>(fit.points.cols()), 2);
    for (int i = 0; i < points.size(); ++i) {
      if (fit.points.col(i).allFinite()) points.set(i, Eigen::Vector2d(fit.points.col(i)));
    }
    OverlayStyle style;
    style.numbers = false;
    drawLandmarks(bgr, points, fit.modelled, scheme, style);
  }
  if (options.label) {
    char text[160];
    if (step.fit) {
      const ViewModel& view = fitter.model().views[static_cast<std::size_t>(step.fit->view)];
      std::snprintf(text, sizeof text, "frame %d  view %+.0f/%+.0f  conf %.2f%s", step.row.frame,
                    view.pitchDeg, view.yawDeg, step.fit->confidence,
                    step.row.success ? "" : "  LOST");
    } else {
      std::snprintf(text, sizeof text, "frame %d  %s", step.row.frame, toString(step.failure));
    }
    const double scale = std::max(0.4, bgr.rows / 600.0);
    const cv::Scalar colour = step.row.success ? cv::Scalar(80, 230, 80) : cv::Scalar(60, 60, 240);
    cv::putText(bgr, text, cv::Point(8, static_cast<int>(22 * scale)), cv::FONT_HERSHEY_SIMPLEX,
                scale * 0.6, cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
    cv::putText(bgr, text, cv::Point(8, static_cast<int>(22 * scale)), cv::FONT_HERSHEY_SIMPLEX,
                scale * 0.6, colour, 1, cv::LINE_AA);
  }
}

}  // namespace clm3d
