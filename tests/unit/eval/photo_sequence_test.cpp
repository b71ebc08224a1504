// The photo sequence's motion and warp: a seeded trajectory that is smooth, stays within its
// ranges and repeats exactly for a seed; the affine that leaves the photo in place at rest and
// moves points where cv::warpAffine moves pixels; the brightness and contrast gains; and a written
// sequence whose truth holds the moved points with missing points left empty.
#include "core/eval/photo_sequence.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "core/common/error.hpp"
#include "core/track/track_table.hpp"
#include "core/video/video_reader.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

TEST(PhotoTrajectory, SmoothWithinRangesAndRepeatableBySeed) {
  PhotoSequenceSettings settings;
  settings.frames = 300;
  settings.seed = 11;
  const auto motion = photoTrajectory(settings, 100.0);
  ASSERT_EQ(motion.size(), 300U);
  double largestRotation = 0.0;
  for (std::size_t t = 0; t < motion.size(); ++t) {
    const PhotoMotion& m = motion[t];
    EXPECT_LE(std::abs(m.dx), 20.0 + 1e-9);
    EXPECT_LE(std::abs(m.dy), 20.0 + 1e-9);
    EXPECT_LE(std::abs(m.scale - 1.0), 0.15 + 1e-9);
    EXPECT_LE(std::abs(m.rotationDeg), 20.0 + 1e-9);
    EXPECT_LE(std::abs(m.brightness - 1.0), 0.2 + 1e-9);
    EXPECT_LE(std::abs(m.contrast - 1.0), 0.2 + 1e-9);
    largestRotation = std::max(largestRotation, std::abs(m.rotationDeg));
    if (t > 0) {
      // Smooth: the fastest sinusoid (period >= 40 frames) moves at most 2 pi / 40 of its range.
      EXPECT_LE(std::abs(m.rotationDeg - motion[t - 1].rotationDeg), 20.0 * 0.16);
      EXPECT_LE(std::abs(m.dx - motion[t - 1].dx), 20.0 * 0.16);
    }
  }
  EXPECT_GT(largestRotation, 5.0);  // it does move
  const auto again = photoTrajectory(settings, 100.0);
  EXPECT_EQ(again[123].dx, motion[123].dx);
  EXPECT_EQ(again[299].contrast, motion[299].contrast);
  settings.seed = 12;
  EXPECT_NE(photoTrajectory(settings, 100.0)[0].dx, motion[0].dx);
}

// A zoom from 0.6 to 1.6 (centre 1.1, range 0.5) and a roll to 45 degrees: the trajectory stays
// in those ranges and uses most of them; a range that would shrink the face to nothing is refused.
TEST(PhotoTrajectory, ZoomAboutItsCentreAndRollWithinTheirRanges) {
  PhotoSequenceSettings settings;
  settings.frames = 600;
  settings.seed = 3;
  settings.scaleCentre = 1.1;
  settings.scaleRange = 0.5;
  settings.rotationDeg = 45.0;
  const auto motion = photoTrajectory(settings, 100.0);
  double smallest = 10.0;
  double largest = 0.0;
  double roll = 0.0;
  for (const PhotoMotion& m : motion) {
    smallest = std::min(smallest, m.scale);
    largest = std::max(largest, m.scale);
    roll = std::max(roll, std::abs(m.rotationDeg));
  }
  EXPECT_GE(smallest, 0.6 - 1e-9);
  EXPECT_LE(largest, 1.6 + 1e-9);
  EXPECT_LT(smallest, 0.85);  // beyond the default range's 0.85..1.15 on both sides
  EXPECT_GT(largest, 1.35);
  EXPECT_GT(roll, 30.0);
  settings.scaleCentre = 0.5;
  EXPECT_THROW(settings.validate(), InputError);
}

TEST(PhotoTransform, RestIsIdentityAndRotationTurnsAboutTheFaceCentre) {
  const Eigen::Vector2d centre(60.0, 40.0);
  const cv::Matx23d rest = photoTransform({}, centre, cv::Size(121, 81), cv::Size(120, 80));
  EXPECT_NEAR(cv::norm(cv::Mat(rest) - cv::Mat(cv::Matx23d(1, 0, 0, 0, 1, 0))), 0.0, 1e-12);
  PhotoMotion turn;
  turn.rotationDeg = 90.0;
  turn.scale = 2.0;
  turn.dx = 5.0;
  const cv::Matx23d m = photoTransform(turn, centre, cv::Size(120, 80), cv::Size(160, 100));
  // 10 pixels right of the centre: scaled to 20 and turned anticlockwise on screen (up, -y), then
  // shifted by dx and by the centring offset (20, 10).
  const cv::Vec3d p(70.0, 40.0, 1.0);
  EXPECT_NEAR(m.row(0).dot(cv::Matx13d(p[0], p[1], p[2])), 60.0 + 5.0 + 20.0, 1e-9);
  EXPECT_NEAR(m.row(1).dot(cv::Matx13d(p[0], p[1], p[2])), 40.0 - 20.0 + 10.0, 1e-9);
}

TEST(PhotoFrame, APixelGoesWhereTheTransformSaysAndGainsApply) {
  cv::Mat photo(60, 80, CV_8UC3, cv::Scalar(100, 100, 100));
  photo.at<cv::Vec3b>(20, 30) = cv::Vec3b(0, 0, 255);
  PhotoMotion motion;
  motion.dx = 7.0;
  motion.dy = -3.0;
  const cv::Matx23d m = photoTransform(motion, {40.0, 30.0}, photo.size(), photo.size());
  const cv::Mat frame = renderPhotoFrame(photo, m, motion, photo.size());
  EXPECT_EQ(frame.at<cv::Vec3b>(17, 37), cv::Vec3b(0, 0, 255));
  EXPECT_EQ(frame.at<cv::Vec3b>(20, 30), cv::Vec3b(100, 100, 100));
  motion.dx = 0.0;
  motion.dy = 0.0;
  motion.brightness = 1.1;
  motion.contrast = 0.8;
  const cv::Mat lit =
      renderPhotoFrame(photo, photoTransform(motion, {40.0, 30.0}, photo.size(), photo.size()),
                       motion, photo.size());
  // 1.1 x (0.8 x (100 - 127.5) + 127.5) = 116.05
  EXPECT_EQ(lit.at<cv::Vec3b>(0, 0)[0], 116);
}

TEST(PhotoSequence, WritesTheMovedPointsMissingOnesEmptyAndRejectsBadInput) {
  const test::TempDir dir;
  cv::Mat photo(90, 121, CV_8UC3, cv::Scalar(80, 120, 160));
  LandmarkSet points(25, 2);
  for (int i = 0; i < 25; ++i) {
    if (i != 18 && i != 24) points.set(i, Eigen::Vector2d(40.0 + 2.0 * i, 30.0 + i));
  }
  PhotoSequenceSettings settings;
  settings.frames = 4;
  settings.seed = 5;
  const SequenceFiles files = SequenceFiles::inFolder(dir / "seq");
  const PhotoSequenceSummary summary =
      writePhotoSequence(photo, points, settings, {"photo.png", "photo.pts"}, files);
  EXPECT_EQ(summary.frameSize, cv::Size(120, 90));
  const TrackTable truth = readTrackTable(files.truth);
  ASSERT_EQ(truth.rows.size(), 4U);
  for (int k = 0; k < 4; ++k) {
    const auto& row = truth.rows[static_cast<std::size_t>(k)];
    const cv::Matx23d& m = summary.transforms[static_cast<std::size_t>(k)];
    EXPECT_FALSE(row.pose.has_value());
    EXPECT_TRUE(std::isnan(row.points(0, 18)));
    EXPECT_TRUE(std::isnan(row.points(1, 24)));
    const Eigen::Vector3d p = points.point(3);
    EXPECT_NEAR(row.points(0, 3), m(0, 0) * p.x() + m(0, 1) * p.y() + m(0, 2), 1e-4);
    EXPECT_NEAR(row.points(1, 3), m(1, 0) * p.x() + m(1, 1) * p.y() + m(1, 2), 1e-4);
  }
  EXPECT_EQ(VideoReader(files.video).frameCount(), 4);
  EXPECT_EQ(readVisibilityTable(files.visibility).size(), 4U);

  LandmarkSet one(25, 2);
  one.set(0, Eigen::Vector2d(10.0, 10.0));
  EXPECT_THROW(writePhotoSequence(photo, one, settings, {}, SequenceFiles::inFolder(dir / "bad")),
               InputError);
  settings.width = 101;
  settings.height = 80;
  EXPECT_THROW(settings.validate(), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
}

}  // namespace
}  // namespace clm3d
