// Tests of the response maps' inner loop (core/fit/detail/window_dots.hpp): the dot products and
// the moments of every window equal sums taken one window at a time, for patch sizes that do and do
// not fill the vectorised kernel's lanes, several filters, and regions whose window count is not
// a multiple of the kernel's group of windows.
#include "core/fit/detail/window_dots.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <opencv2/core.hpp>
#include <vector>

namespace clm3d {
namespace {

cv::Mat randomRegion(int rows, int cols, int seed) {
  cv::Mat region(rows, cols, CV_32FC1);
  cv::RNG rng(static_cast<std::uint64_t>(seed));
  rng.fill(region, cv::RNG::UNIFORM, 0.0, 1.0);
  return region;
}

TEST(WindowDots, EqualsOneWindowAtATime) {
  std::cout << "window dots vectorised on this processor: "
            << (windowDotsVectorised() ? "yes" : "no") << "\n";
  struct Case {
    int patch, rows, cols, units;
  };
  for (const Case& c : {Case{20, 28, 28, 1}, Case{20, 30, 27, 3}, Case{7, 15, 16, 2},
                        Case{9, 9, 9, 1}, Case{1, 4, 5, 1}, Case{17, 25, 21, 4}}) {
    SCOPED_TRACE("patch " + std::to_string(c.patch) + ", region " + std::to_string(c.rows) + "x" +
                 std::to_string(c.cols) + ", units " + std::to_string(c.units));
    const cv::Mat region = randomRegion(c.rows, c.cols, c.patch * 100 + c.units);
    Eigen::MatrixXf filters = Eigen::MatrixXf::Random(c.patch * c.patch, c.units);
    const int rows = c.rows - c.patch + 1;
    const int cols = c.cols - c.patch + 1;
    std::vector<float> dots(static_cast<std::size_t>(rows * cols * c.units), -999.0f);
    windowDots(region, filters, c.patch, dots.data());
    for (int y = 0; y < rows; ++y) {
      for (int x = 0; x < cols; ++x) {
        for (int k = 0; k < c.units; ++k) {
          double expected = 0.0;
          for (int i = 0; i < c.patch; ++i) {
            for (int j = 0; j < c.patch; ++j) {
              expected +=
                  static_cast<double>(region.at<float>(y + i, x + j)) * filters(i * c.patch + j, k);
            }
          }
          ASSERT_NEAR(dots[static_cast<std::size_t>((y * cols + x) * c.units + k)], expected,
                      1e-4 * (1.0 + std::abs(expected)))
              << "window (" << x << ", " << y << "), unit " << k;
        }
      }
    }
  }
}

TEST(WindowMoments, EqualOneWindowAtATime) {
  const int patch = 6;
  const cv::Mat region = randomRegion(14, 11, 7);
  std::vector<double> mean;
  std::vector<double> variance;
  windowMoments(region, patch, mean, variance);
  const int rows = region.rows - patch + 1;
  const int cols = region.cols - patch + 1;
  ASSERT_EQ(mean.size(), static_cast<std::size_t>(rows * cols));
  ASSERT_EQ(variance.size(), mean.size());
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < cols; ++x) {
      cv::Scalar m;
      cv::Scalar sd;
      cv::meanStdDev(region(cv::Rect(x, y, patch, patch)), m, sd);
      const std::size_t at = static_cast<std::size_t>(y * cols + x);
      EXPECT_NEAR(mean[at], m[0], 1e-9);
      EXPECT_NEAR(variance[at], sd[0] * sd[0], 1e-9);
    }
  }
}

TEST(WindowMoments, FlatWindowHasNoVariance) {
  const cv::Mat region(8, 8, CV_32FC1, cv::Scalar(0.25));
  std::vector<double> mean;
  std::vector<double> variance;
  windowMoments(region, 5, mean, variance);
  ASSERT_EQ(mean.size(), 16u);  // 4 x 4 windows of 5 x 5 in 8 x 8
  ASSERT_EQ(variance.size(), mean.size());
  for (std::size_t i = 0; i < mean.size(); ++i) {
    EXPECT_NEAR(mean[i], 0.25, 1e-12);
    EXPECT_LT(std::abs(variance[i]), 1e-12);
  }
}

}  // namespace
}  // namespace clm3d
