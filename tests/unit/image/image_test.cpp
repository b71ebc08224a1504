// Tests of core/image: bilinear patch sampling and the pyramid coordinate convention that
// training and fitting share.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "core/common/error.hpp"
#include "core/image/patch_sampling.hpp"
#include "core/image/pyramid.hpp"

namespace clm3d {
namespace {

// f(x, y) = a + b x + c y at pixel centres.
cv::Mat ramp(int width, int height, float a, float b, float c) {
  cv::Mat image(height, width, CV_32F);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) image.at<float>(y, x) = a + b * x + c * y;
  }
  return image;
}

// A Gaussian blob centred on (cx, cy) with the given sigma (pixels).
cv::Mat blob(int width, int height, double cx, double cy, double sigma) {
  cv::Mat image(height, width, CV_32F);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double d2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
      image.at<float>(y, x) = static_cast<float>(std::exp(-d2 / (2 * sigma * sigma)));
    }
  }
  return image;
}

// Intensity-weighted centroid of an image (the blob's centre).
Eigen::Vector2d centroid(const cv::Mat& image) {
  double sum = 0, sx = 0, sy = 0;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const double v = image.at<float>(y, x);
      sum += v;
      sx += v * x;
      sy += v * y;
    }
  }
  return {sx / sum, sy / sum};
}

TEST(PatchSampling, BilinearIsExactOnALinearRamp) {
  const cv::Mat image = ramp(40, 30, 2.0f, 0.5f, -0.25f);
  const int size = 7;
  const Eigen::Vector2d centre(17.3, 11.65);
  const Eigen::VectorXf patch = samplePatch(image, centre, size);
  ASSERT_EQ(patch.size(), size * size);
  for (int r = 0; r < size; ++r) {
    for (int c = 0; c < size; ++c) {
      const double x = centre.x() + c - 3;
      const double y = centre.y() + r - 3;
      EXPECT_NEAR(patch[r * size + c], 2.0 + 0.5 * x - 0.25 * y, 1e-4) << r << "," << c;
    }
  }
  EXPECT_NEAR(sampleBilinear(image, 3.25, 4.5), 2.0 + 0.5 * 3.25 - 0.25 * 4.5, 1e-5);
}

TEST(PatchSampling, IntegerCentreReturnsThePixelsThemselves) {
  const cv::Mat image = blob(20, 20, 9.0, 9.0, 2.0);
  const Eigen::VectorXf patch = samplePatch(image, {9.0, 9.0}, 5);
  for (int r = 0; r < 5; ++r) {
    for (int c = 0; c < 5; ++c) EXPECT_EQ(patch[r * 5 + c], image.at<float>(7 + r, 7 + c));
  }
}

TEST(PatchSampling, BlobSampledAtItsCentreIsCentredInThePatch) {
  // Odd and even sizes: the blob's centre is the patch's centre ((size - 1) / 2).
  for (int size : {9, 10}) {
    const cv::Mat image = blob(64, 48, 30.4, 21.7, 1.5);
    const Eigen::VectorXf patch = samplePatch(image, {30.4, 21.7}, size);
    cv::Mat asImage(size, size, CV_32F);
    for (int i = 0; i < size * size; ++i) asImage.at<float>(i / size, i % size) = patch[i];
    const Eigen::Vector2d c = centroid(asImage);
    EXPECT_NEAR(c.x(), (size - 1) / 2.0, 0.05) << size;
    EXPECT_NEAR(c.y(), (size - 1) / 2.0, 0.05) << size;
  }
}

TEST(PatchSampling, BorderIsReplicated) {
  const cv::Mat image = ramp(10, 10, 0.0f, 1.0f, 10.0f);
  const Eigen::VectorXf patch = samplePatch(image, {-5.0, -5.0}, 3);
  for (int i = 0; i < 9; ++i) EXPECT_FLOAT_EQ(patch[i], 0.0f);
  EXPECT_FLOAT_EQ(sampleBilinear(image, 20.0, 20.0), 99.0f);
}

TEST(PatchSampling, InteriorFastPathAgreesWithPointSampling) {
  cv::Mat image(40, 50, CV_32F);
  cv::randu(image, 0.0f, 1.0f);
  for (const Eigen::Vector2d& centre :
       {Eigen::Vector2d(20.3, 17.8), Eigen::Vector2d(9.5, 9.5), Eigen::Vector2d(40.01, 30.99),
        Eigen::Vector2d(3.2, 35.0)}) {
    const Eigen::VectorXf patch = samplePatch(image, centre, 12);
    for (int r = 0; r < 12; ++r) {
      for (int c = 0; c < 12; ++c) {
        EXPECT_NEAR(patch[r * 12 + c],
                    sampleBilinear(image, centre.x() + c - 5.5, centre.y() + r - 5.5), 1e-5f);
      }
    }
  }
}

TEST(PatchSampling, RejectsBadInput) {
  Eigen::VectorXf out(9);
  EXPECT_THROW(samplePatch(cv::Mat(), {0, 0}, 3, out), std::invalid_argument);
  EXPECT_THROW(samplePatch(cv::Mat(5, 5, CV_8U), {0, 0}, 3, out), std::invalid_argument);
  EXPECT_THROW(samplePatch(ramp(5, 5, 0, 1, 1), {0, 0}, 4, out), std::invalid_argument);
}

TEST(Pyramid, LevelsHalveTheSize) {
  const auto pyramid = gaussianPyramid(ramp(101, 60, 0, 1, 1), 4);
  ASSERT_EQ(pyramid.size(), 4u);
  EXPECT_EQ(pyramid[0].cols, 101);
  EXPECT_EQ(pyramid[1].cols, 51);
  EXPECT_EQ(pyramid[1].rows, 30);
  EXPECT_EQ(pyramid[3].cols, 13);
  EXPECT_THROW(gaussianPyramid(cv::Mat(4, 4, CV_8U), 2), InputError);
  EXPECT_THROW(gaussianPyramid(ramp(4, 4, 0, 1, 1), 0), InputError);
}

TEST(Pyramid, CoordinatesMapBetweenLevels) {
  const Eigen::Vector2d p(41.0, 27.0);
  EXPECT_TRUE(toPyramidLevel(p, 0).isApprox(p));
  EXPECT_NEAR(toPyramidLevel(p, 1).x(), 20.5, 1e-12);
  EXPECT_NEAR(toPyramidLevel(p, 2).y(), 6.75, 1e-12);
  EXPECT_TRUE(fromPyramidLevel(toPyramidLevel(p, 2), 2).isApprox(p));

  // A blob's centre lands where the convention says, at every level.
  const Eigen::Vector2d centre(70.0, 45.0);
  const auto pyramid = gaussianPyramid(blob(160, 120, centre.x(), centre.y(), 6.0), 3);
  for (int s = 0; s < 3; ++s) {
    const Eigen::Vector2d expected = toPyramidLevel(centre, s);
    const Eigen::Vector2d found = centroid(pyramid[static_cast<std::size_t>(s)]);
    EXPECT_NEAR(found.x(), expected.x(), 0.05) << "level " << s;
    EXPECT_NEAR(found.y(), expected.y(), 0.05) << "level " << s;
  }
}

TEST(Pyramid, GreyFloatFromBgra) {
  cv::Mat bgra(2, 2, CV_8UC4, cv::Scalar(255, 255, 255, 0));
  const cv::Mat grey = toGreyFloat(bgra);
  EXPECT_EQ(grey.type(), CV_32FC1);
  EXPECT_NEAR(grey.at<float>(0, 0), 1.0f, 1e-6);
}

}  // namespace
}  // namespace clm3d
