// Gradient-orientation features around 2D points, in a frame normalised for the face's position,
// size and roll: what the descent refiner regresses point corrections from. Each point gives a
// window of 4x4 cells with 8 signed orientation bins (128 values, normalised so that contrast and
// brightness do not matter). The frame is the similarity that maps the refiner's mean shape onto
// the current points, so a face at any scale and roll gives the same features.
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include "core/model/descent_refiner.hpp"

namespace clm3d {

// Image coordinates = scale * rotation(angle) * normalised + translation.
struct SimilarityFrame {
  double scale = 1.0;
  double angle = 0.0;  // radians
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();

  Eigen::Vector2d toImage(const Eigen::Vector2d& normalised) const;
  Eigen::Vector2d toNormalised(const Eigen::Vector2d& image) const;
};

// The least-squares similarity taking `from` (2 x N) onto `to` (2 x N). N >= 2.
SimilarityFrame fitSimilarity(const Eigen::Matrix2Xd& from, const Eigen::Matrix2Xd& to);

// Features of `points` (normalised coordinates, 2 x N) seen through `frame` in `grey` (CV_32FC1),
// each window `window` normalised units wide. Returns N * kDescentFeaturesPerPoint values
// (core/model/descent_refiner.hpp).
Eigen::VectorXf descentFeatures(const cv::Mat& grey, const SimilarityFrame& frame,
                                const Eigen::Matrix2Xd& points, double window);

}  // namespace clm3d
