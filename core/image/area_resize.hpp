// Reduction of an image by area averaging: each output pixel is the mean of the input it covers,
// partly covered pixels weighted by their overlap (the weights of cv::resize's INTER_AREA). The
// fitter makes its working image this way every frame (core/fit/working_image.hpp); for the
// fractional factors it needs (a face slightly larger than the training size) cv::resize's
// general area path cost a fifth of a frame's search, while these weights are computed once per
// axis and applied in two separable passes.
#pragma once

#include <opencv2/core/mat.hpp>

namespace clm3d {

// `image` (CV_8UC1 or CV_32FC1, non-empty) reduced to `size`, at most its own size in both
// directions, into `out` as CV_32FC1 multiplied by `gain` (1 / 255 takes 8-bit grey to [0, 1]).
// Throws Error for another type or a size that is empty or larger than the image.
void reduceByArea(const cv::Mat& image, cv::Size size, double gain, cv::Mat& out);

}  // namespace clm3d
