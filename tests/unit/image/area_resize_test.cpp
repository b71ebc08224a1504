// Tests of the area reduction (core/image/area_resize.hpp): it equals cv::resize's INTER_AREA on
// float images for whole and fractional factors, takes 8-bit grey to [0, 1], keeps a flat image
// flat, and refuses sizes it cannot make.
#include "core/image/area_resize.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

TEST(ReduceByArea, MatchesOpenCvAreaResize) {
  cv::Mat image(97, 131, CV_32FC1);
  cv::RNG rng(5);
  rng.fill(image, cv::RNG::UNIFORM, 0.0, 1.0);
  for (const cv::Size size : {cv::Size(120, 90), cv::Size(65, 48), cv::Size(43, 97),
                              cv::Size(131, 40), cv::Size(17, 11), cv::Size(1, 1)}) {
    SCOPED_TRACE(std::to_string(size.width) + "x" + std::to_string(size.height));
    cv::Mat expected;
    cv::resize(image, expected, size, 0, 0, cv::INTER_AREA);
    cv::Mat reduced;
    reduceByArea(image, size, 1.0, reduced);
    ASSERT_EQ(reduced.type(), CV_32FC1);
    ASSERT_EQ(reduced.size(), size);
    EXPECT_LT(cv::norm(reduced, expected, cv::NORM_INF), 1e-4);
  }
}

TEST(ReduceByArea, EightBitGreyToUnitRange) {
  cv::Mat image(40, 60, CV_8UC1);
  cv::RNG rng(9);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  cv::Mat expected;
  cv::resize(image, expected, cv::Size(37, 25), 0, 0, cv::INTER_AREA);
  expected.convertTo(expected, CV_32F, 1.0 / 255.0);
  cv::Mat reduced;
  reduceByArea(image, cv::Size(37, 25), 1.0 / 255.0, reduced);
  // OpenCV rounds its 8-bit result to whole grey levels; this keeps the fraction.
  EXPECT_LE(cv::norm(reduced, expected, cv::NORM_INF), 0.5 / 255.0 + 1e-6);
}

TEST(ReduceByArea, FlatStaysFlat) {
  const cv::Mat image(33, 29, CV_32FC1, cv::Scalar(0.375));
  cv::Mat reduced;
  reduceByArea(image, cv::Size(20, 17), 2.0, reduced);
  double low = 0.0;
  double high = 0.0;
  cv::minMaxLoc(reduced, &low, &high);
  EXPECT_NEAR(low, 0.75, 1e-6);
  EXPECT_NEAR(high, 0.75, 1e-6);
}

TEST(ReduceByArea, RefusesWhatItCannotMake) {
  const cv::Mat image(10, 10, CV_32FC1, cv::Scalar(0));
  cv::Mat out;
  EXPECT_THROW(reduceByArea(image, cv::Size(11, 5), 1.0, out), Error);
  EXPECT_THROW(reduceByArea(image, cv::Size(0, 5), 1.0, out), Error);
  EXPECT_THROW(reduceByArea(cv::Mat(10, 10, CV_8UC3), cv::Size(5, 5), 1.0, out), Error);
  EXPECT_THROW(reduceByArea(cv::Mat(), cv::Size(5, 5), 1.0, out), Error);
}

}  // namespace
}  // namespace clm3d
