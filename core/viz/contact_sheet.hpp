// A grid of equally sized images with a caption under each, for pictures a person judges at a
// glance (a head from the 15 training views, later mean patches per view).
#pragma once

#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

namespace clm3d {

// Tiles are BGR or BGRA of one size; transparent pixels are composited on `background`.
// captions may be empty or hold one string per tile. Returns a BGR image.
cv::Mat makeContactSheet(const std::vector<cv::Mat>& tiles, int columns,
                         const std::vector<std::string>& captions = {},
                         const cv::Scalar& background = cv::Scalar(48, 48, 48));

// Composites a BGRA image over a solid colour; BGR input is returned as is.
cv::Mat flattenAlpha(const cv::Mat& image, const cv::Scalar& background);

}  // namespace clm3d
