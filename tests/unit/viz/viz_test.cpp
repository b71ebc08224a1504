#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"
#include "core/viz/contact_sheet.hpp"
#include "core/viz/image_file.hpp"
#include "core/viz/landmark_overlay.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

TEST(ImageFile, PngRoundTripKeepsAlpha) {
  test::TempDir dir;
  cv::Mat image(12, 20, CV_8UC4, cv::Scalar(10, 20, 30, 0));
  image(cv::Rect(5, 3, 4, 4)).setTo(cv::Scalar(200, 100, 50, 255));
  writeImage(dir / "a.png", image);
  const cv::Mat back = readImage(dir / "a.png", true);
  ASSERT_EQ(back.type(), CV_8UC4);
  EXPECT_EQ(cv::norm(back, image, cv::NORM_INF), 0.0);
  EXPECT_EQ(readImage(dir / "a.png").type(), CV_8UC3);
}

TEST(ImageFile, FloatTiffRoundTrip) {
  test::TempDir dir;
  cv::Mat depth(8, 8, CV_32F, cv::Scalar(512.25f));
  writeImage(dir / "d.tiff", depth);
  const cv::Mat back = readImage(dir / "d.tiff", true);
  ASSERT_EQ(back.type(), CV_32F);
  EXPECT_FLOAT_EQ(back.at<float>(3, 4), 512.25f);
}

TEST(ImageFile, ErrorsNameTheFile) {
  test::TempDir dir;
  test::writeFile(dir / "broken.png", "not an image at all");
  try {
    readImage(dir / "broken.png");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.png"), std::string::npos);
  }
  EXPECT_THROW(readImage(dir / "absent.png"), InputError);
  EXPECT_THROW(writeImage(dir / "noext", cv::Mat(2, 2, CV_8UC3)), InputError);
  EXPECT_THROW(writeImage(dir / "x.unknownformat", cv::Mat(2, 2, CV_8UC3)), InputError);
}

TEST(LandmarkOverlay, DrawsRegionColourAtPointsOnly) {
  const Scheme& scheme = Scheme::thesis25();
  cv::Mat image(200, 200, CV_8UC3, cv::Scalar(0, 0, 0));
  LandmarkSet points(scheme.size(), 2);
  points.set(11, Eigen::Vector2d(100, 120));  // nose tip
  drawLandmarks(image, points, {}, scheme, {false, 1.0});
  const RgbColour c = scheme.regions()[static_cast<std::size_t>(scheme.regionOf(11))].colour;
  const cv::Vec3b centre = image.at<cv::Vec3b>(120, 100);
  EXPECT_EQ(centre, cv::Vec3b(c.b, c.g, c.r));
  EXPECT_EQ(image.at<cv::Vec3b>(20, 20), cv::Vec3b(0, 0, 0));
  // Hidden points are drawn hollow: the centre keeps the background.
  cv::Mat hollow(200, 200, CV_8UC3, cv::Scalar(0, 0, 0));
  points.set(11, Eigen::Vector2d(100, 120));
  std::vector<bool> visible(static_cast<std::size_t>(scheme.size()), true);
  visible[11] = false;
  drawLandmarks(hollow, points, visible, scheme, {false, 3.0});
  EXPECT_EQ(hollow.at<cv::Vec3b>(120, 100), cv::Vec3b(0, 0, 0));
  EXPECT_GT(cv::countNonZero(hollow.reshape(1)), 0);
}

TEST(ContactSheet, TilesAndComposites) {
  std::vector<cv::Mat> tiles;
  for (int i = 0; i < 5; ++i) tiles.emplace_back(10, 16, CV_8UC4, cv::Scalar(0, 0, 255, 255));
  tiles[1].setTo(cv::Scalar(0, 0, 0, 0));  // fully transparent
  const cv::Mat sheet = makeContactSheet(tiles, 3, {}, cv::Scalar(7, 8, 9));
  EXPECT_EQ(sheet.cols, 48);
  EXPECT_EQ(sheet.rows, 20);
  EXPECT_EQ(sheet.at<cv::Vec3b>(2, 2), cv::Vec3b(0, 0, 255));
  EXPECT_EQ(sheet.at<cv::Vec3b>(2, 18), cv::Vec3b(7, 8, 9));
  EXPECT_EQ(sheet.at<cv::Vec3b>(15, 40), cv::Vec3b(7, 8, 9));  // empty sixth cell
  EXPECT_THROW(makeContactSheet({}, 3), Error);
  tiles[2] = cv::Mat(5, 5, CV_8UC4);
  EXPECT_THROW(makeContactSheet(tiles, 3), Error);
}

}  // namespace
}  // namespace clm3d
