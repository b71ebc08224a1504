// The fitter's working image: the part of an input frame around the face, resampled so the face
// has the inter-ocular distance the model's patches were trained at, as a Gaussian pyramid; and
// the exact mapping between input pixels and pixels of each pyramid level. Resampling only the
// face region keeps the per-frame cost independent of the video's resolution.
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <vector>

namespace clm3d {

struct WorkingImage {
  std::vector<cv::Mat> levels;  // grey CV_32F in [0, 1]; level s has 1/2^s of level 0's resolution
  // Level-0 working pixel = gain .* input pixel + offset (both OpenCV pixel-centre conventions).
  Eigen::Vector2d gain{1.0, 1.0};
  Eigen::Vector2d offset{0.0, 0.0};

  Eigen::Vector2d toLevel(const Eigen::Vector2d& input, int level) const;
  Eigen::Vector2d fromLevel(const Eigen::Vector2d& atLevel, int level) const;
};

// Cuts the box [boxMin, boxMax] (input pixels, clipped to the image) out of `input` (CV_8UC1/3/4
// or CV_32FC1 grey in [0, 1]), scales it by `scale` (area averaging when shrinking, bilinear when
// enlarging) and builds `levels` pyramid levels into `out`, reusing its buffers. Throws InputError
// for an empty or unsupported image, a box outside the image or a scale that is not positive.
void makeWorkingImage(const cv::Mat& input, const Eigen::Vector2d& boxMin,
                      const Eigen::Vector2d& boxMax, double scale, int levels, WorkingImage& out);

}  // namespace clm3d
