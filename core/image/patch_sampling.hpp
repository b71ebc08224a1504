// Sub-pixel square patches sampled from a grey image by bilinear interpolation, and their
// normalisation for normalised cross-correlation. Training builds its texture models from these
// patches and the fitter compares them with the same sampler, so the two agree to the sub-pixel.
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

namespace clm3d {

// Samples a size x size patch centred on `centre` (pixels, OpenCV convention: integer coordinates
// are pixel centres) into `out` (size * size values, row-major: out[r * size + c]). Sample (r, c)
// is at centre + (c - (size - 1) / 2, r - (size - 1) / 2), so for an even size the centre falls
// between the two middle samples. Bilinear interpolation; outside the image the border pixel is
// repeated. `image` must be CV_32FC1 and non-empty; out.size() must be size * size
// (std::invalid_argument otherwise).
void samplePatch(const cv::Mat& image, const Eigen::Vector2d& centre, int size,
                 Eigen::Ref<Eigen::VectorXf> out);

// Convenience form returning a new vector.
Eigen::VectorXf samplePatch(const cv::Mat& image, const Eigen::Vector2d& centre, int size);

// The bilinear value at one point (border replicate), the same arithmetic as samplePatch.
float sampleBilinear(const cv::Mat& image, double x, double y);

}  // namespace clm3d
