// Checks on pictures the tests render (plots, contact sheets), shared by the suites that draw them.
#pragma once

#include <opencv2/core.hpp>

namespace clm3d {

// Whether every pixel within `margin` of the edges of a BGR picture is white: nothing drawn runs
// off the picture.
inline bool borderIsWhite(const cv::Mat& image, int margin = 3) {
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const bool border =
          x < margin || y < margin || x >= image.cols - margin || y >= image.rows - margin;
      if (border && image.at<cv::Vec3b>(y, x) != cv::Vec3b(255, 255, 255)) return false;
    }
  }
  return true;
}

}  // namespace clm3d
