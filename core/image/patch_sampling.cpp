#include "core/image/patch_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace clm3d {
namespace {

void checkImage(const cv::Mat& image) {
  if (image.empty() || image.type() != CV_32FC1) {
    throw std::invalid_argument("samplePatch: the image must be a non-empty CV_32FC1 image");
  }
}

// Bilinear value with the border replicated; the image is known to be valid.
float bilinear(const cv::Mat& image, double x, double y) {
  const double maxX = image.cols - 1;
  const double maxY = image.rows - 1;
  x = std::clamp(x, 0.0, maxX);
  y = std::clamp(y, 0.0, maxY);
  const int x0 = static_cast<int>(std::floor(x));
  const int y0 = static_cast<int>(std::floor(y));
  const int x1 = std::min(x0 + 1, image.cols - 1);
  const int y1 = std::min(y0 + 1, image.rows - 1);
  const float fx = static_cast<float>(x - x0);
  const float fy = static_cast<float>(y - y0);
  const float* row0 = image.ptr<float>(y0);
  const float* row1 = image.ptr<float>(y1);
  const float top = row0[x0] + fx * (row0[x1] - row0[x0]);
  const float bottom = row1[x0] + fx * (row1[x1] - row1[x0]);
  return top + fy * (bottom - top);
}

}  // namespace

void samplePatch(const cv::Mat& image, const Eigen::Vector2d& centre, int size,
                 Eigen::Ref<Eigen::VectorXf> out) {
  checkImage(image);
  if (size < 1 || out.size() != static_cast<Eigen::Index>(size) * size) {
    throw std::invalid_argument("samplePatch: the output must hold size * size values");
  }
  const double half = (size - 1) / 2.0;
  const double left = centre.x() - half;
  const double top = centre.y() - half;
  // Samples are whole pixels apart, so every sample has the same fractional offsets. When the
  // patch and its right/bottom neighbours lie inside the image, interpolate with fixed weights
  // and no clamping (the fitter's inner loop); otherwise fall back to the clamped form.
  if (std::isfinite(left) && std::isfinite(top) && left >= 0.0 && top >= 0.0 &&
      left + size < image.cols && top + size < image.rows) {
    const int x0 = static_cast<int>(left);
    const int y0 = static_cast<int>(top);
    const float fx = static_cast<float>(left - x0);
    const float fy = static_cast<float>(top - y0);
    const float w00 = (1.0f - fx) * (1.0f - fy), w01 = fx * (1.0f - fy);
    const float w10 = (1.0f - fx) * fy, w11 = fx * fy;
    float* target = out.data();
    for (int r = 0; r < size; ++r) {
      const float* row0 = image.ptr<float>(y0 + r) + x0;
      const float* row1 = image.ptr<float>(y0 + r + 1) + x0;
      for (int c = 0; c < size; ++c) {
        target[r * size + c] =
            w00 * row0[c] + w01 * row0[c + 1] + w10 * row1[c] + w11 * row1[c + 1];
      }
    }
    return;
  }
  for (int r = 0; r < size; ++r) {
    const double y = top + r;
    for (int c = 0; c < size; ++c) {
      out[r * size + c] = bilinear(image, left + c, y);
    }
  }
}

Eigen::VectorXf samplePatch(const cv::Mat& image, const Eigen::Vector2d& centre, int size) {
  Eigen::VectorXf out(static_cast<Eigen::Index>(std::max(size, 0)) * std::max(size, 0));
  samplePatch(image, centre, size, out);
  return out;
}

float sampleBilinear(const cv::Mat& image, double x, double y) {
  checkImage(image);
  return bilinear(image, x, y);
}

}  // namespace clm3d
