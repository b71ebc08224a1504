#include "core/track/fit_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <string>

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

// The fit's patches (its templates made from `frame` where its search read it) and landmarks.
void drawResult(cv::Mat& bgr, const cv::Mat& frame, const FitResult& fit, Fitter& fitter,
                const Scheme& scheme, const FitOverlayOptions& options) {
  if (options.patches) {
    // Made before anything is drawn: `bgr` may be `frame` itself.
    const FitTemplates templates = fitter.templates(frame, fit);
    std::size_t entry = 0;
    for (std::size_t i = 0; i < fit.modelled.size() && entry < templates.values.size(); ++i) {
      if (!fit.modelled[i]) continue;
      const Eigen::VectorXf& values = templates.values[entry++];
      const int size = static_cast<int>(std::lround(std::sqrt(static_cast<double>(values.size()))));
      pastePatch(bgr, templateImage(values, size), fit.points.col(static_cast<Eigen::Index>(i)),
                 templates.pixelSize);
    }
  }
  if (options.landmarks) {
    LandmarkSet points(static_cast<int>(fit.points.cols()), 2);
    for (int i = 0; i < points.size(); ++i) {
      if (fit.points.col(i).allFinite()) points.set(i, Eigen::Vector2d(fit.points.col(i)));
    }
    OverlayStyle style;
    style.numbers = false;
    drawLandmarks(bgr, points, fit.modelled, scheme, style);
  }
}

// "WHAT  view P/Y  conf C" (or WHAT alone without a fit) in the corner, green when it passed.
void drawLabel(cv::Mat& bgr, const std::string& what, const FitResult* fit, const Fitter& fitter,
               bool passed, const char* failedMark) {
  char text[200];
  if (fit != nullptr && fit->view >= 0 &&
      fit->view < static_cast<int>(fitter.model().views.size())) {
    const ViewModel& view = fitter.model().views[static_cast<std::size_t>(fit->view)];
    std::snprintf(text, sizeof text, "%s  view %+.0f/%+.0f  p %.2f%s", what.c_str(), view.pitchDeg,
                  view.yawDeg, fit->probability, passed ? "" : failedMark);
  } else {
    std::snprintf(text, sizeof text, "%s", what.c_str());
  }
  const double scale = std::max(0.4, bgr.rows / 600.0);
  const cv::Scalar colour = passed ? cv::Scalar(80, 230, 80) : cv::Scalar(60, 60, 240);
  const cv::Point corner(8, static_cast<int>(22 * scale));
  cv::putText(bgr, text, corner, cv::FONT_HERSHEY_SIMPLEX, scale * 0.6, cv::Scalar(0, 0, 0), 3,
              cv::LINE_AA);
  cv::putText(bgr, text, corner, cv::FONT_HERSHEY_SIMPLEX, scale * 0.6, colour, 1, cv::LINE_AA);
}

}  // namespace

void drawFitOverlay(cv::Mat& bgr, const cv::Mat& frame, const TrackStep& step, Fitter& fitter,
                    const Scheme& scheme, const FitOverlayOptions& options) {
  if (step.fit) drawResult(bgr, frame, *step.fit, fitter, scheme, options);
  if (!options.label) return;
  const std::string what = "frame " + std::to_string(step.row.frame);
  if (step.fit) {
    drawLabel(bgr, what, &*step.fit, fitter, step.row.success, "  LOST");
  } else {
    drawLabel(bgr, what + "  " + toString(step.failure), nullptr, fitter, step.row.success, "");
  }
}

void drawPhotoOverlay(cv::Mat& bgr, const cv::Mat& photo, const FitResult& fit, bool passed,
                      const std::string& name, Fitter& fitter, const Scheme& scheme,
                      const FitOverlayOptions& options) {
  drawResult(bgr, photo, fit, fitter, scheme, options);
  if (options.label) drawLabel(bgr, name, &fit, fitter, passed, "  REJECTED");
}

}  // namespace clm3d
