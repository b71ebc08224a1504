#include "core/refine/detail/descent_features.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/common/error.hpp"
#include "core/image/patch_sampling.hpp"

namespace clm3d {

namespace {

constexpr int kCells = 4;
constexpr int kCellPixels = 4;
constexpr int kBins = 8;
constexpr int kSamples = kCells * kCellPixels;  // gradient samples per side
constexpr int kSide = kSamples + 2;             // one border sample each side
constexpr float kClip = 0.2f;                   // cap on one value after normalising
constexpr float kPi = std::numbers::pi_v<float>;

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

// atan(t) for t in [0, 1]: Cephes's atanf (one reduction by pi/4, a degree-9 odd polynomial),
// within 2 float ulps of libm's, a few times cheaper than atan2f and branch-free enough for the
// compiler to keep it in registers.
inline float atanUnit(float t) {
  const bool upper = t > 0.41421356f;  // tan(pi/8)
  const float r = upper ? (t - 1.0f) / (t + 1.0f) : t;
  const float z = r * r;
  const float poly = (((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
                      3.33329491539e-1f) *
                         z * r +
                     r;
  return upper ? poly + 0.25f * kPi : poly;
}

// The gradient's direction in [0, 2 pi), as atan2(gy, gx) moved into [0, 2 pi) (gx, gy not both
// zero): the first octant's angle from the smaller over the larger component, then reflected.
// Selects rather than branches, so that a row of them vectorises.
inline float direction(float gx, float gy) {
  const float ax = std::abs(gx);
  const float ay = std::abs(gy);
  const bool steep = ay > ax;
  const float t = (steep ? ax : ay) / std::max(steep ? ay : ax, std::numeric_limits<float>::min());
  const float octant = atanUnit(t);
  float angle = steep ? 0.5f * kPi - octant : octant;
  angle = gx < 0.0f ? kPi - angle : angle;
  return gy < 0.0f ? 2.0f * kPi - angle : angle;
}

// The kSide x kSide samples of `grey` at origin + u * axisU + v * axisV (bilinear, the border
// replicated), row-major into `patch`.
void sampleWindow(const cv::Mat& grey, double originX, double originY, double ux, double uy,
                  double vx, double vy, float* patch) {
  // The window's corners bound its samples: inside the image with a pixel to spare, no sample
  // needs the border.
  double lowX = originX, highX = originX, lowY = originY, highY = originY;
  for (const double u : {0.0, kSide - 1.0}) {
    for (const double v : {0.0, kSide - 1.0}) {
      lowX = std::min(lowX, originX + u * ux + v * vx);
      highX = std::max(highX, originX + u * ux + v * vx);
      lowY = std::min(lowY, originY + u * uy + v * vy);
      highY = std::max(highY, originY + u * uy + v * vy);
    }
  }
  const bool inside =
      lowX >= 0.0 && lowY >= 0.0 && highX < grey.cols - 1.01 && highY < grey.rows - 1.01;
  const std::size_t step = grey.step1();
  const float* pixels = grey.ptr<float>(0);
  for (int v = 0; v < kSide; ++v) {
    const double rowX = originX + v * vx;
    const double rowY = originY + v * vy;
    float* out = patch + v * kSide;
    if (!inside) {
      for (int u = 0; u < kSide; ++u) out[u] = sampleBilinear(grey, rowX + u * ux, rowY + u * uy);
      continue;
    }
    for (int u = 0; u < kSide; ++u) {
      const double x = rowX + u * ux;
      const double y = rowY + u * uy;
      const int x0 = static_cast<int>(x);  // x, y >= 0: truncation is the floor
      const int y0 = static_cast<int>(y);
      const auto fx = static_cast<float>(x - x0);
      const auto fy = static_cast<float>(y - y0);
      const float* top = pixels + static_cast<std::size_t>(y0) * step + x0;
      const float* bottom = top + step;
      const float upper = top[0] + fx * (top[1] - top[0]);
      const float lower = bottom[0] + fx * (bottom[1] - bottom[0]);
      out[u] = upper + fy * (lower - upper);
    }
  }
}

}  // namespace

Eigen::VectorXf descentFeatures(const cv::Mat& grey, const Similarity2& frame,
                                const Eigen::Matrix2Xd& points, double window) {
  if (grey.type() != CV_32FC1) throw Error("descentFeatures: need a float grey image");
  const int n = static_cast<int>(points.cols());
  Eigen::VectorXf out = Eigen::VectorXf::Zero(n * kDescentFeaturesPerPoint);
  // One sample step in image pixels; the window has kSide samples (one border each side for the
  // central differences), patch pixel (u, v) at centre + R ((u, v) - (kSide - 1) / 2) * step.
  const double step = window / kSamples;
  const double c = std::cos(frame.angle) * frame.scale * step;
  const double s = std::sin(frame.angle) * frame.scale * step;
  const double half = (kSide - 1) / 2.0;
  // Sampled here rather than with cv::warpAffine, whose set-up cost was most of a small window's,
  // and in floating point rather than its 1/32-pixel fixed point (as core/fit's sampleRegion).
  float patch[kSide * kSide];
  for (int p = 0; p < n; ++p) {
    const Eigen::Vector2d centre = frame.apply(Eigen::Vector2d(points.col(p)));
    if (!centre.allFinite()) continue;  // no window: its block stays zero
    sampleWindow(grey, centre.x() - c * half + s * half, centre.y() - s * half - c * half, c, s, -s,
                 c, patch);
    float* hist = out.data() + p * kDescentFeaturesPerPoint;
    for (int y = 1; y <= kSamples; ++y) {
      const float* row = patch + y * kSide;
      const float* up = row - kSide;
      const float* down = row + kSide;
      const int cellY = (y - 1) / kCellPixels;
      // The row's magnitudes and bins first (a loop without branches, vectorised), then each
      // shared between its two bins.
      float magnitudes[kSamples];
      float bins[kSamples];
      for (int x = 0; x < kSamples; ++x) {
        const float gx = row[x + 2] - row[x];
        const float gy = down[x + 1] - up[x + 1];
        magnitudes[x] = std::sqrt(gx * gx + gy * gy);
        bins[x] = direction(gx, gy) * kBins / (2.0f * kPi);
      }
      for (int x = 0; x < kSamples; ++x) {
        const float magnitude = magnitudes[x];
        if (magnitude <= 0.0f) continue;
        const float bin = bins[x];
        const int lower = static_cast<int>(bin) % kBins;
        const float upperShare = bin - std::floor(bin);
        const int cell = cellY * kCells + x / kCellPixels;
        hist[cell * kBins + lower] += magnitude * (1.0f - upperShare);
        hist[cell * kBins + (lower + 1) % kBins] += magnitude * upperShare;
      }
    }
    normaliseBlock(hist, kDescentFeaturesPerPoint);
  }
  return out;
}

}  // namespace clm3d
