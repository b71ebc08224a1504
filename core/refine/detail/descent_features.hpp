// Gradient-orientation features around 2D points, in a frame normalised for the face's position,
// size and roll: what the descent refiner regresses point corrections from. Each point gives a
// window of 4x4 cells with 8 signed orientation bins (128 values, normalised so that contrast and
// brightness do not matter). The frame is the similarity that maps the refiner's mean shape onto
// the current points, so a face at any scale and roll gives the same features.
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include "core/geometry/similarity2.hpp"
#include "core/model/descent_refiner.hpp"

namespace clm3d {

// Features of `points` (normalised coordinates, 2 x N) seen through `frame` (normalised to image
// coordinates) in `grey` (CV_32FC1), each window `window` normalised units wide. Returns N *
// kDescentFeaturesPerPoint values (core/model/descent_refiner.hpp).
Eigen::VectorXf descentFeatures(const cv::Mat& grey, const Similarity2& frame,
                                const Eigen::Matrix2Xd& points, double window);

}  // namespace clm3d
