#include "core/refine/descent_features.hpp"

#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"

namespace clm3d {

namespace {

constexpr int kCells = 4;
constexpr int kCellPixels = 4;
constexpr int kBins = 8;
constexpr int kSamples = kCells * kCellPixels;  // gradient samples per side
constexpr float kClip = 0.2f;                   // cap on one value after normalising

// Normalises to unit length, caps each value and normalises again, so that a few strong edges do
// not dominate the window.
void normaliseBlock(float* values, int count) {
  for (int pass = 0; pass < 2; ++pass) {
    double sum = 0.0;
    for (int i = 0; i < count; ++i) sum += double(values[i]) * values[i];
    const float norm = static_cast<float>(std::sqrt(sum)) + 1e-6f;
    for (int i = 0; i < count; ++i) {
      values[i] /= norm;
      if (pass == 0) values[i] = std::min(values[i], kClip);
    }
  }
}

}  // namespace

Eigen::VectorXf descentFeatures(const cv::Mat& grey, const Similarity2& frame,
                                const Eigen::Matrix2Xd& points, double window) {
  if (grey.type() != CV_32FC1) throw Error("descentFeatures: need a float grey image");
  const int n = static_cast<int>(points.cols());
  Eigen::VectorXf out = Eigen::VectorXf::Zero(n * kDescentFeaturesPerPoint);
  // One sample step in image pixels; the window has kSamples + 2 samples (one border each side
  // for the central differences).
  const double step = window / kSamples;
  const double c = std::cos(frame.angle) * frame.scale * step;
  const double s = std::sin(frame.angle) * frame.scale * step;
  constexpr int side = kSamples + 2;
  cv::Mat patch(side, side, CV_32FC1);
  for (int p = 0; p < n; ++p) {
    const Eigen::Vector2d centre = frame.apply(Eigen::Vector2d(points.col(p)));
    // Maps patch pixel (u, v) to the image: centre + R * ((u, v) - (side - 1) / 2) * step.
    const double half = (side - 1) / 2.0;
    cv::Matx23d map(c, -s, centre.x() - c * half + s * half, s, c,
                    centre.y() - s * half - c * half);
    cv::warpAffine(grey, patch, map, patch.size(), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                   cv::BORDER_REPLICATE);
    float* hist = out.data() + p * kDescentFeaturesPerPoint;
    for (int y = 1; y <= kSamples; ++y) {
      const float* row = patch.ptr<float>(y);
      const float* up = patch.ptr<float>(y - 1);
      const float* down = patch.ptr<float>(y + 1);
      const int cellY = (y - 1) / kCellPixels;
      for (int x = 1; x <= kSamples; ++x) {
        const float gx = row[x + 1] - row[x - 1];
        const float gy = down[x] - up[x];
        const float magnitude = std::sqrt(gx * gx + gy * gy);
        if (magnitude <= 0.0f) continue;
        float angle = std::atan2(gy, gx);
        if (angle < 0.0f) angle += 2.0f * std::numbers::pi_v<float>;
        const float bin = angle * kBins / (2.0f * std::numbers::pi_v<float>);
        const int lower = static_cast<int>(bin) % kBins;
        const float upperShare = bin - std::floor(bin);
        const int cell = cellY * kCells + (x - 1) / kCellPixels;
        hist[cell * kBins + lower] += magnitude * (1.0f - upperShare);
        hist[cell * kBins + (lower + 1) % kBins] += magnitude * upperShare;
      }
    }
    normaliseBlock(hist, kDescentFeaturesPerPoint);
  }
  return out;
}

}  // namespace clm3d
