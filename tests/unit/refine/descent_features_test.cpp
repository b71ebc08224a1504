// Tests of the refiner's features (core/refine/descent_features): a brightness ramp's gradient
// falls in the orientation bins of its direction, in every quadrant and on the bins' edges, and
// the features agree with the warpAffine and atan2 computation they replaced (the refiner of a
// model trained before was learnt on those), inside the image and where the windows reach past
// its border.
#include "core/refine/detail/descent_features.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <random>
#include <vector>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

constexpr int kBins = 8;
constexpr int kCellsPerWindow = 16;

// The features as computed before: each window cut with cv::warpAffine (1/32-pixel fixed point),
// each gradient's direction from std::atan2.
Eigen::VectorXf referenceFeatures(const cv::Mat& grey, const Similarity2& frame,
                                  const Eigen::Matrix2Xd& points, double window) {
  constexpr int samples = 16;
  constexpr int side = samples + 2;
  const int n = static_cast<int>(points.cols());
  Eigen::VectorXf out = Eigen::VectorXf::Zero(n * kDescentFeaturesPerPoint);
  const double step = window / samples;
  const double c = std::cos(frame.angle) * frame.scale * step;
  const double s = std::sin(frame.angle) * frame.scale * step;
  cv::Mat patch(side, side, CV_32FC1);
  for (int p = 0; p < n; ++p) {
    const Eigen::Vector2d centre = frame.apply(Eigen::Vector2d(points.col(p)));
    const double half = (side - 1) / 2.0;
    cv::Matx23d map(c, -s, centre.x() - c * half + s * half, s, c,
                    centre.y() - s * half - c * half);
    cv::warpAffine(grey, patch, map, patch.size(), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                   cv::BORDER_REPLICATE);
    float* hist = out.data() + p * kDescentFeaturesPerPoint;
    for (int y = 1; y <= samples; ++y) {
      for (int x = 1; x <= samples; ++x) {
        const float gx = patch.at<float>(y, x + 1) - patch.at<float>(y, x - 1);
        const float gy = patch.at<float>(y + 1, x) - patch.at<float>(y - 1, x);
        const float magnitude = std::sqrt(gx * gx + gy * gy);
        if (magnitude <= 0.0f) continue;
        float angle = std::atan2(gy, gx);
        if (angle < 0.0f) angle += 2.0f * std::numbers::pi_v<float>;
        const float bin = angle * kBins / (2.0f * std::numbers::pi_v<float>);
        const int lower = static_cast<int>(bin) % kBins;
        const float upperShare = bin - std::floor(bin);
        const int cell = (y - 1) / 4 * 4 + (x - 1) / 4;
        hist[cell * kBins + lower] += magnitude * (1.0f - upperShare);
        hist[cell * kBins + (lower + 1) % kBins] += magnitude * upperShare;
      }
    }
    for (int pass = 0; pass < 2; ++pass) {
      double sum = 0.0;
      for (int i = 0; i < kDescentFeaturesPerPoint; ++i) sum += double(hist[i]) * hist[i];
      const float norm = static_cast<float>(std::sqrt(sum)) + 1e-6f;
      for (int i = 0; i < kDescentFeaturesPerPoint; ++i) {
        hist[i] /= norm;
        if (pass == 0) hist[i] = std::min(hist[i], 0.2f);
      }
    }
  }
  return out;
}

// A textured float image: blurred noise, so that every window has gradients in every direction.
cv::Mat texturedImage(int width, int height, std::uint64_t seed) {
  cv::Mat image(height, width, CV_32FC1);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, 0.0, 1.0);
  cv::GaussianBlur(image, image, cv::Size(0, 0), 2.0);
  return image;
}

TEST(DescentFeatures, ARampsGradientFallsInTheBinsOfItsDirection) {
  // I(x, y) = x cos(t) + y sin(t): every gradient points along t, so each cell's histogram holds
  // (1 - f, f) of one magnitude in bins floor(b) and floor(b) + 1 (b = t / (2 pi / 8), f its
  // fraction), and after normalising, every cell the same.
  for (const double degrees : {0.0, 10.0, 45.0, 60.0, 90.0, 100.0, 135.0, 170.0, 180.0, 200.0,
                               225.0, 260.0, 270.0, 300.0, 315.0, 350.0}) {
    SCOPED_TRACE(degrees);
    const double t = degrees * std::numbers::pi / 180.0;
    cv::Mat ramp(120, 120, CV_32FC1);
    for (int y = 0; y < ramp.rows; ++y) {
      for (int x = 0; x < ramp.cols; ++x) {
        ramp.at<float>(y, x) = static_cast<float>(0.01 * (x * std::cos(t) + y * std::sin(t)));
      }
    }
    const Similarity2 identity{};
    const Eigen::Matrix2Xd point = Eigen::Vector2d(60.0, 60.0);
    const Eigen::VectorXf features = descentFeatures(ramp, identity, point, 24.0);
    ASSERT_EQ(features.size(), kDescentFeaturesPerPoint);
    const double bin = std::fmod(t * kBins / (2.0 * std::numbers::pi), kBins);
    const int lower = static_cast<int>(std::floor(bin + 1e-9)) % kBins;
    const double fraction = std::max(0.0, bin - std::floor(bin + 1e-9));
    // Every cell (1 - f, f) in bins lower, lower + 1; then normalised as the features are (unit
    // length, each value capped at 0.2, unit length again).
    std::vector<double> expected(kDescentFeaturesPerPoint, 0.0);
    for (int c = 0; c < kCellsPerWindow; ++c) {
      expected[c * kBins + lower] += 1.0 - fraction;
      expected[c * kBins + (lower + 1) % kBins] += fraction;
    }
    for (int pass = 0; pass < 2; ++pass) {
      double sum = 0.0;
      for (const double v : expected) sum += v * v;
      for (double& v : expected)
        v = pass == 0 ? std::min(v / std::sqrt(sum), 0.2) : v / std::sqrt(sum);
    }
    for (int i = 0; i < kDescentFeaturesPerPoint; ++i) {
      EXPECT_NEAR(features[i], expected[static_cast<std::size_t>(i)], 2e-4)
          << "cell " << i / kBins << " bin " << i % kBins;
    }
  }
}

TEST(DescentFeatures, AgreeWithTheWarpAffineAndAtan2Features) {
  const cv::Mat image = texturedImage(200, 160, 7);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double largest = 0.0;
  double total = 0.0;
  Eigen::Index count = 0;
  for (int trial = 0; trial < 20; ++trial) {
    // A frame of any roll and size; points spread over the image and, every other trial, some
    // reaching past its border (the border replicated).
    Similarity2 frame;
    frame.angle = 2.0 * std::numbers::pi * uniform(random);
    frame.scale = 20.0 + 40.0 * uniform(random);
    const double reach = trial % 2 == 0 ? 0.1 : -0.2;
    frame.translation = Eigen::Vector2d(100.0, 80.0);
    Eigen::Matrix2Xd points(2, 12);
    for (Eigen::Index p = 0; p < points.cols(); ++p) {
      const Eigen::Vector2d at(image.cols * (reach + (1.0 - 2.0 * reach) * uniform(random)),
                               image.rows * (reach + (1.0 - 2.0 * reach) * uniform(random)));
      points.col(p) = frame.inverse(at);
    }
    const double window = 0.2 + 0.3 * uniform(random);
    const Eigen::VectorXf now = descentFeatures(image, frame, points, window);
    const Eigen::VectorXf before = referenceFeatures(image, frame, points, window);
    ASSERT_EQ(now.size(), before.size());
    ASSERT_TRUE(now.allFinite());
    for (Eigen::Index p = 0; p < points.cols(); ++p) {
      const auto block = [&](const Eigen::VectorXf& f) {
        return f.segment(p * kDescentFeaturesPerPoint, kDescentFeaturesPerPoint);
      };
      const Eigen::Vector2d at = frame.apply(Eigen::Vector2d(points.col(p)));
      if ((at.x() < 0.0 || at.x() > image.cols - 1) && (at.y() < 0.0 || at.y() > image.rows - 1)) {
        // Beyond a corner the samples are replicated border pixels, mostly the corner's: our
        // sampler finds no gradient where every sample is the corner pixel (a zero block), while
        // warpAffine's fixed point found some. Not compared.
        continue;
      }
      largest = std::max(largest, double((block(now) - block(before)).cwiseAbs().maxCoeff()));
      total += (block(now) - block(before)).cwiseAbs().sum();
      count += kDescentFeaturesPerPoint;
    }
  }
  // The windows' samples differ by up to 1/64 pixel of interpolation (warpAffine's fixed point),
  // which matters most in the smallest windows (samples a quarter of a pixel apart), and the
  // directions by a float rounding; the blocks are unit vectors of 128 values, each about 0.09.
  // Measured: mean difference 0.00025, largest 0.007; windows sampled a pixel off or turned the
  // wrong way differ by tens of times that.
  std::cout << "[ mean difference " << total / static_cast<double>(count) << ", largest " << largest
            << " ]\n";
  EXPECT_LT(largest, 0.02);
  EXPECT_LT(total / static_cast<double>(count), 0.001);
}

TEST(DescentFeatures, AWindowWithoutAFinitePlaceIsZeroAndOthersAreUnchanged) {
  const cv::Mat image = texturedImage(100, 100, 3);
  Similarity2 frame;
  frame.scale = 30.0;
  frame.translation = Eigen::Vector2d(50.0, 50.0);
  Eigen::Matrix2Xd points(2, 2);
  points << 0.1, std::numeric_limits<double>::quiet_NaN(), -0.2, 0.0;
  const Eigen::VectorXf features = descentFeatures(image, frame, points, 0.4);
  EXPECT_TRUE(features.tail(kDescentFeaturesPerPoint).isZero());
  const Eigen::VectorXf alone = descentFeatures(image, frame, points.leftCols(1), 0.4);
  EXPECT_EQ(features.head(kDescentFeaturesPerPoint), alone);
  EXPECT_THROW((void)descentFeatures(cv::Mat(10, 10, CV_8UC1), frame, points, 0.4), Error);
}

}  // namespace
}  // namespace clm3d
