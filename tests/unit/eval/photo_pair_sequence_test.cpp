// Two photos side by side (core/eval/photo_pair_sequence.hpp): two truth rows a frame with the
// face column, each face's points where its half of the video shows its photo's marked pixel,
// the two faces on trajectories of their own, and bad input refused.
#include "core/eval/photo_pair_sequence.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"
#include "core/track/track_table.hpp"
#include "core/video/video_reader.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// A flat photo whose point 0 is a bright dot and the other points a spread box around it.
cv::Mat markedPhoto(const cv::Scalar& colour, LandmarkSet& points) {
  cv::Mat photo(96, 128, CV_8UC3, colour);
  points = LandmarkSet(25, 2);
  for (int i = 0; i < 25; ++i) points.set(i, Eigen::Vector2d(44.0 + 2.0 * i, 30.0 + 1.5 * i));
  cv::circle(photo, cv::Point(44, 30), 3, cv::Scalar(255, 255, 255), cv::FILLED);
  return photo;
}

TEST(PhotoPairSequence, EachFaceInItsHalfWhereItsTruthSays) {
  const test::TempDir dir;
  LandmarkSet leftPoints, rightPoints;
  const cv::Mat left = markedPhoto(cv::Scalar(40, 40, 40), leftPoints);
  const cv::Mat right = markedPhoto(cv::Scalar(60, 60, 60), rightPoints);
  PhotoSequenceSettings settings;
  settings.frames = 5;
  settings.brightnessRange = 0.0;
  settings.contrastRange = 0.0;
  const SequenceFiles files = SequenceFiles::inFolder(dir / "pair");
  const PhotoPairSummary summary =
      writePhotoPairSequence(left, leftPoints, right, rightPoints, settings, {"a.png", "a.pts"},
                             {"b.png", "b.pts"}, files);
  EXPECT_EQ(summary.frameSize, cv::Size(256, 96));
  const TrackTable truth = readTrackTable(files.truth);
  ASSERT_EQ(truth.extraColumns, std::vector<std::string>{"face"});
  ASSERT_EQ(truth.rows.size(), 10u);
  VideoReader video(files.video);
  cv::Mat frame;
  bool moveApart = false;
  for (int t = 0; t < 5; ++t) {
    ASSERT_TRUE(video.read(frame));
    cv::Mat grey;
    cv::cvtColor(frame, grey, cv::COLOR_BGR2GRAY);
    for (int k = 0; k < 2; ++k) {
      const TrackRow& row = truth.rows[static_cast<std::size_t>(2 * t + k)];
      EXPECT_EQ(row.frame, t);
      EXPECT_EQ(row.extraCells, std::vector<std::string>{std::to_string(k)});
      const Eigen::Vector2d dot = row.points.col(0);
      EXPECT_EQ(dot.x() >= 128.0, k == 1) << "face " << k << " in its half at frame " << t;
      EXPECT_GT(grey.at<unsigned char>(cvRound(dot.y()), cvRound(dot.x())), 200)
          << "face " << k << "'s marked point at frame " << t;
    }
    const Eigen::Vector2d shiftLeft =
        truth.rows[static_cast<std::size_t>(2 * t)].points.col(0) - leftPoints.point(0).head<2>();
    const Eigen::Vector2d shiftRight =
        truth.rows[static_cast<std::size_t>(2 * t + 1)].points.col(0) -
        rightPoints.point(0).head<2>() - Eigen::Vector2d(128.0, 0.0);
    moveApart = moveApart || (shiftLeft - shiftRight).norm() > 0.5;
  }
  EXPECT_TRUE(moveApart) << "each face moves on a trajectory of its own";

  LandmarkSet other(68, 2);
  EXPECT_THROW(writePhotoPairSequence(left, leftPoints, right, other, settings, {}, {},
                                      SequenceFiles::inFolder(dir / "bad")),
               InputError);
  EXPECT_THROW(writePhotoPairSequence(cv::Mat(), leftPoints, right, rightPoints, settings, {}, {},
                                      SequenceFiles::inFolder(dir / "bad")),
               InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
}

}  // namespace
}  // namespace clm3d
