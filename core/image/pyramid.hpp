// Gaussian image pyramids and the coordinate mapping between their levels. Training samples
// texture patches at every level and the fitter searches coarse to fine on the same pyramid, so
// both use these functions and this convention.
//
// Convention: level s has 1/2^s of the resolution of level 0 (cv::pyrDown: 5-tap Gaussian, then
// the even pixels). Pixel centres are at integer coordinates (OpenCV); pyrDown centres pixel i of
// the smaller level on pixel 2i of the larger one, so pixel p at level 0 is p_s = p / 2^s at level
// s (not (p + 0.5) / 2^s - 0.5, which holds for area averaging; the test checks a blob's centre).
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <vector>

namespace clm3d {

// Levels 0..levels-1 of a single-channel CV_32F image; level 0 is the image itself (shared, not
// copied). Throws InputError if the image is not CV_32FC1, is empty, or levels < 1; a level
// smaller than 1 pixel is not made (a 1x1 level repeats instead).
std::vector<cv::Mat> gaussianPyramid(const cv::Mat& grey, int levels);

// Level-0 pixel coordinates to level-`level` coordinates, and back.
Eigen::Vector2d toPyramidLevel(const Eigen::Vector2d& level0, int level);
Eigen::Vector2d fromPyramidLevel(const Eigen::Vector2d& atLevel, int level);

// A BGR(A) CV_8U image to grey CV_32F in [0, 1] (ITU-R 601 weights, as cv::cvtColor).
cv::Mat toGreyFloat(const cv::Mat& bgrOrBgra);

}  // namespace clm3d
