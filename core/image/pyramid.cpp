#include "core/image/pyramid.hpp"

#include <opencv2/imgproc.hpp>
#include <string>

#include "core/common/error.hpp"

namespace clm3d {

std::vector<cv::Mat> gaussianPyramid(const cv::Mat& grey, int levels) {
  if (grey.empty() || grey.type() != CV_32FC1) {
    throw InputError("gaussianPyramid: the image must be a non-empty single-channel float image");
  }
  if (levels < 1) {
    throw InputError("gaussianPyramid: levels must be at least 1, got " + std::to_string(levels));
  }
  std::vector<cv::Mat> pyramid;
  pyramid.reserve(static_cast<std::size_t>(levels));
  pyramid.push_back(grey);
  for (int s = 1; s < levels; ++s) {
    const cv::Mat& previous = pyramid.back();
    if (previous.cols < 2 && previous.rows < 2) {
      pyramid.push_back(previous);
      continue;
    }
    cv::Mat next;
    cv::pyrDown(previous, next, cv::Size((previous.cols + 1) / 2, (previous.rows + 1) / 2),
                cv::BORDER_REPLICATE);
    pyramid.push_back(next);
  }
  return pyramid;
}

Eigen::Vector2d toPyramidLevel(const Eigen::Vector2d& level0, int level) {
  const double factor = static_cast<double>(1 << level);
  return level0 / factor;
}

Eigen::Vector2d fromPyramidLevel(const Eigen::Vector2d& atLevel, int level) {
  const double factor = static_cast<double>(1 << level);
  return atLevel * factor;
}

cv::Mat toGreyFloat(const cv::Mat& bgrOrBgra) {
  if (bgrOrBgra.empty() || bgrOrBgra.depth() != CV_8U ||
      (bgrOrBgra.channels() != 3 && bgrOrBgra.channels() != 4)) {
    throw InputError("toGreyFloat: expected an 8-bit BGR or BGRA image");
  }
  cv::Mat grey;
  cv::cvtColor(bgrOrBgra, grey,
               bgrOrBgra.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  cv::Mat result;
  grey.convertTo(result, CV_32F, 1.0 / 255.0);
  return result;
}

}  // namespace clm3d
