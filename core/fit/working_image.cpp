#include "core/fit/working_image.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"
#include "core/image/area_resize.hpp"

namespace clm3d {

Eigen::Vector2d WorkingImage::toLevel(const Eigen::Vector2d& input, int level) const {
  return (gain.cwiseProduct(input) + offset) / std::ldexp(1.0, level);
}

Eigen::Vector2d WorkingImage::fromLevel(const Eigen::Vector2d& atLevel, int level) const {
  return (atLevel * std::ldexp(1.0, level) - offset).cwiseQuotient(gain);
}

void makeWorkingImage(const cv::Mat& input, const Eigen::Vector2d& boxMin,
                      const Eigen::Vector2d& boxMax, double scale, int levels, WorkingImage& out) {
  if (input.empty()) throw InputError("fit: the image is empty");
  const int type = input.type();
  if (type != CV_8UC1 && type != CV_8UC3 && type != CV_8UC4 && type != CV_32FC1) {
    throw InputError("fit: unsupported image type (need 8-bit grey, BGR or BGRA, or float grey)");
  }
  if (!(scale > 0.0) || !std::isfinite(scale)) throw InputError("fit: the image scale must be > 0");
  if (levels < 1) throw InputError("fit: need at least one pyramid level");
  if (!boxMin.allFinite() || !boxMax.allFinite())
    throw InputError("fit: the face box is not finite");

  const int x0 = std::clamp(static_cast<int>(std::floor(boxMin.x())), 0, input.cols - 1);
  const int y0 = std::clamp(static_cast<int>(std::floor(boxMin.y())), 0, input.rows - 1);
  const int x1 = std::clamp(static_cast<int>(std::ceil(boxMax.x())) + 1, x0 + 1, input.cols);
  const int y1 = std::clamp(static_cast<int>(std::ceil(boxMax.y())) + 1, y0 + 1, input.rows);
  const cv::Mat roi = input(cv::Rect(x0, y0, x1 - x0, y1 - y0));

  // Grey of the region only, at the input resolution.
  cv::Mat grey8;
  const cv::Mat* grey = &roi;
  if (type == CV_8UC3) {
    cv::cvtColor(roi, grey8, cv::COLOR_BGR2GRAY);
    grey = &grey8;
  } else if (type == CV_8UC4) {
    cv::cvtColor(roi, grey8, cv::COLOR_BGRA2GRAY);
    grey = &grey8;
  }

  const int width = std::max(1, static_cast<int>(std::lround(roi.cols * scale)));
  const int height = std::max(1, static_cast<int>(std::lround(roi.rows * scale)));
  const double gainX = static_cast<double>(width) / roi.cols;
  const double gainY = static_cast<double>(height) / roi.rows;

  if (out.levels.size() != static_cast<std::size_t>(levels)) out.levels.resize(levels);
  if (width < roi.cols && height <= roi.rows) {
    // Area averaging, as training reduces its photos (core/train/photo_samples.cpp).
    reduceByArea(*grey, cv::Size(width, height), grey->type() == CV_32FC1 ? 1.0 : 1.0 / 255.0,
                 out.levels[0]);
  } else {
    cv::Mat resized;
    if (width == roi.cols && height == roi.rows) {
      resized = *grey;
    } else {
      cv::resize(*grey, resized, cv::Size(width, height), 0, 0, cv::INTER_LINEAR);
    }
    if (resized.type() == CV_32FC1) {
      resized.copyTo(out.levels[0]);
    } else {
      resized.convertTo(out.levels[0], CV_32F, 1.0 / 255.0);
    }
  }
  for (int level = 1; level < levels; ++level) {
    const cv::Mat& finer = out.levels[level - 1];
    if (finer.cols < 2 || finer.rows < 2) {
      finer.copyTo(out.levels[level]);
    } else {
      cv::pyrDown(finer, out.levels[level]);
    }
  }
  // cv::resize samples source pixel (x' + 0.5) / gain - 0.5 of the region for target pixel x',
  // so x' = gain (x - x0 + 0.5) - 0.5 in input pixels x.
  out.gain = {gainX, gainY};
  out.offset = {gainX * (0.5 - x0) - 0.5, gainY * (0.5 - y0) - 0.5};
}

}  // namespace clm3d
