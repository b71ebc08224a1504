// clm3d synth --photo through the real binary (core/eval/photo_sequence): a render of a procedural
// head with its 25 projected points and a red marker becomes a moving sequence whose truth is the
// affine of the points and whose marker lands where the affine says; the same seed gives the same
// sequence, another seed another; a 68-point file leaves the earlobes missing; bad landmark files
// exit 1 naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <string>

#include "core/eval/photo_sequence.hpp"
#include "core/geometry/projection.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/track_table.hpp"
#include "core/video/video_reader.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using test::runClm3d;

// A 322x242 photo (odd-sized crops are common; the frames become 322x242) of the held-out head at
// yaw 10 over mid-grey, its projected points, and a red 5x5 marker centred at `marker`.
struct PhotoFiles {
  test::TempDir dir;
  fs::path photo, points;
  LandmarkSet truth{25, 2};
  Eigen::Vector2d marker{150.0, 60.0};
  PhotoFiles() {
    const SynthHead& head = test::fitTestHead(test::kHeldOutHead);
    const Camera camera = Camera::fromVerticalFov(322, 242, 40.0);
    const Eigen::Matrix3Xd landmarks = head.landmarks.matrix();
    const double iodMm = (landmarks.col(7) - landmarks.col(10)).norm();
    const Pose pose =
        Pose::fromDegrees(0.0, 10.0, 0.0, {0.0, 0.0, -camera.focalY() * iodMm / 60.0});
    OffscreenRenderer renderer(head.mesh);
    const RenderResult render = renderer.render(pose, camera);
    cv::Mat image(render.bgra.rows, render.bgra.cols, CV_8UC3);
    for (int y = 0; y < image.rows; ++y) {
      for (int x = 0; x < image.cols; ++x) {
        const cv::Vec4b s = render.bgra.at<cv::Vec4b>(y, x);
        for (int c = 0; c < 3; ++c) {
          image.at<cv::Vec3b>(y, x)[c] =
              static_cast<unsigned char>((s[3] * s[c] + (255 - s[3]) * 128) / 255);
        }
      }
    }
    image(cv::Rect(148, 58, 5, 5)).setTo(cv::Scalar(0, 0, 255));
    photo = dir / "head.png";
    writeImage(photo, image);
    const Eigen::Matrix2Xd projected = projectPoints(landmarks, pose, camera);
    for (int i = 0; i < 25; ++i) truth.set(i, Eigen::Vector2d(projected.col(i)));
    points = dir / "head.pts";
    writeLandmarks(points, truth, Scheme::thesis25());
  }
};

const PhotoFiles& photoFiles() {
  static const PhotoFiles files;
  return files;
}

TEST(SynthPhotoCli, TruthIsTheAffineOfThePointsAndTheMarkerMovesWithIt) {
  const PhotoFiles& f = photoFiles();
  const fs::path out = f.dir / "seq";
  const auto result = runClm3d("synth --photo " + f.photo.string() + " --landmarks " +
                               f.points.string() + " --frames 40 --seed 7 --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "40 frames 322x242")) << result.output;
  const TrackTable truth = readTrackTable(out / "truth.csv");
  ASSERT_EQ(truth.rows.size(), 40U);
  ASSERT_EQ(truth.landmarkCount, 25);
  EXPECT_TRUE(fs::exists(out / "sequence.json"));
  EXPECT_TRUE(fs::exists(out / "truth-visibility.csv"));

  // The core's trajectory for the same settings gives the transforms the truth must follow.
  PhotoSequenceSettings settings;
  settings.frames = 40;
  settings.seed = 7;
  const PhotoFace face = photoFace(f.truth);
  const auto motion = photoTrajectory(settings, face.size);
  VideoReader video(out / "sequence.avi");
  double largestShift = 0.0;
  for (int k = 0; k < 40; ++k) {
    const TrackRow& row = truth.rows[static_cast<std::size_t>(k)];
    const cv::Matx23d m = photoTransform(motion[static_cast<std::size_t>(k)], face.centre,
                                         cv::Size(322, 242), cv::Size(322, 242));
    const auto apply = [&m](const Eigen::Vector2d& p) {
      return Eigen::Vector2d(m(0, 0) * p.x() + m(0, 1) * p.y() + m(0, 2),
                             m(1, 0) * p.x() + m(1, 1) * p.y() + m(1, 2));
    };
    for (int i = 0; i < 25; ++i) {
      const Eigen::Vector2d expected = apply(f.truth.point(i).head<2>());
      EXPECT_NEAR(row.points(0, i), expected.x(), 1e-3) << "frame " << k << " point " << i;
      EXPECT_NEAR(row.points(1, i), expected.y(), 1e-3) << "frame " << k << " point " << i;
    }
    // The transform is in the extra columns too.
    ASSERT_EQ(row.extraCells.size(), 8U);
    EXPECT_NEAR(std::stod(row.extraCells[2]), m(0, 2), 1e-6);
    EXPECT_NEAR(std::stod(row.extraCells[4]), m(1, 1), 1e-9);

    cv::Mat frame;
    ASSERT_TRUE(video.read(frame)) << "frame " << k;
    const Eigen::Vector2d at = apply(f.marker);
    largestShift = std::max(largestShift, (at - f.marker).norm());
    const cv::Point nearest(static_cast<int>(std::lround(at.x())),
                            static_cast<int>(std::lround(at.y())));
    ASSERT_TRUE(cv::Rect(0, 0, frame.cols, frame.rows).contains(nearest)) << "frame " << k;
    const cv::Vec3b pixel = frame.at<cv::Vec3b>(nearest);
    EXPECT_GT(pixel[2], pixel[1] + 100) << "frame " << k << " at " << at.transpose();
    EXPECT_GT(pixel[2], pixel[0] + 100) << "frame " << k << " at " << at.transpose();
  }
  EXPECT_GT(largestShift, 5.0);  // it did move
}

TEST(SynthPhotoCli, TheSameSeedGivesTheSameSequenceAnotherSeedAnother) {
  const PhotoFiles& f = photoFiles();
  const auto run = [&f](const std::string& name, int seed) {
    const fs::path out = f.dir / name;
    const auto result = runClm3d("synth --photo " + f.photo.string() + " --landmarks " +
                                 f.points.string() + " --frames 6 --size 200x160 --seed " +
                                 std::to_string(seed) + " --out " + out.string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    return out;
  };
  const fs::path a = run("seed-3a", 3);
  const fs::path b = run("seed-3b", 3);
  const fs::path c = run("seed-4", 4);
  EXPECT_EQ(test::readFile(a / "truth.csv"), test::readFile(b / "truth.csv"));
  EXPECT_NE(test::readFile(a / "truth.csv"), test::readFile(c / "truth.csv"));
  VideoReader va(a / "sequence.avi");
  VideoReader vb(b / "sequence.avi");
  cv::Mat fa;
  cv::Mat fb;
  for (int k = 0; k < 6; ++k) {
    ASSERT_TRUE(va.read(fa));
    ASSERT_TRUE(vb.read(fb));
    EXPECT_EQ(fa.size(), cv::Size(200, 160));
    EXPECT_EQ(cv::norm(fa, fb, cv::NORM_INF), 0.0) << "frame " << k;
  }
}

// --photo-roll and --photo-zoom set the motion's ranges (recorded in sequence.json); a zoom that
// is not SMALLEST:LARGEST is refused as bad usage.
TEST(SynthPhotoCli, RollAndZoomRangesAreTheOnesGiven) {
  const PhotoFiles& f = photoFiles();
  const fs::path out = f.dir / "roll-zoom";
  const std::string base = "synth --photo " + f.photo.string() + " --landmarks " +
                           f.points.string() + " --frames 4 --size 200x160 ";
  const auto result = runClm3d(base + "--photo-roll 45 --photo-zoom 0.6:1.6 --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto json = nlohmann::json::parse(test::readFile(out / "sequence.json"));
  EXPECT_DOUBLE_EQ(json["motion"]["rotation_degrees"].get<double>(), 45.0);
  EXPECT_NEAR(json["motion"]["scale_centre"].get<double>(), 1.1, 1e-12);
  EXPECT_NEAR(json["motion"]["scale_range"].get<double>(), 0.5, 1e-12);
  const auto bad = runClm3d(base + "--photo-zoom 1.6:0.6 --out " + (f.dir / "bad").string());
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_TRUE(test::contains(bad.output, "--photo-zoom")) << bad.output;
}

TEST(SynthPhotoCli, A68PointFileKeepsThePointsWithAFixedCounterpart) {
  const PhotoFiles& f = photoFiles();
  LandmarkSet ibug(68, 2);
  for (int i = 0; i < 68; ++i) ibug.set(i, Eigen::Vector2d(100.0 + i, 80.0 + (i % 7) * 5.0));
  const fs::path pts = f.dir / "ibug.pts";
  writeLandmarks(pts, ibug, Scheme::ibug68());
  const fs::path out = f.dir / "ibug-seq";
  const auto result = runClm3d("synth --photo " + f.photo.string() + " --landmarks " +
                               pts.string() + " --frames 3 --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "points 19/25")) << result.output;
  const TrackTable truth = readTrackTable(out / "truth.csv");
  ASSERT_EQ(truth.rows.size(), 3U);
  for (const TrackRow& row : truth.rows) {
    EXPECT_TRUE(std::isnan(row.points(0, 18)));   // point 19, left earlobe
    EXPECT_TRUE(std::isnan(row.points(0, 24)));   // point 25, right earlobe
    EXPECT_TRUE(std::isnan(row.points(0, 19)));   // point 20, left cheek: the jaw contour's
    EXPECT_TRUE(std::isnan(row.points(0, 22)));   // point 23, right chin side
    EXPECT_FALSE(std::isnan(row.points(0, 21)));  // point 22, chin centre: iBUG point 8
  }
  // Empty cells, as the tracks CSV writes a missing point.
  EXPECT_TRUE(test::contains(test::readFile(out / "truth.csv"), ",,"))
      << test::readFile(out / "truth.csv");
}

// --beside puts a second photo in the right half on its own trajectory: two truth rows a frame
// (face 0 left, face 1 right), each face's points inside its own half, the frame twice as wide;
// --beside without its points is a usage error naming the option.
TEST(SynthPhotoCli, BesideGivesTwoFacesEachInItsHalf) {
  const PhotoFiles& f = photoFiles();
  const fs::path out = f.dir / "pair";
  const std::string base = "synth --photo " + f.photo.string() + " --landmarks " +
                           f.points.string() + " --frames 5 --beside " + f.photo.string();
  const auto result =
      runClm3d(base + " --beside-landmarks " + f.points.string() + " --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "5 frames 644x242")) << result.output;
  const TrackTable truth = readTrackTable(out / "truth.csv");
  ASSERT_EQ(truth.extraColumns, std::vector<std::string>{"face"});
  ASSERT_EQ(truth.rows.size(), 10U);
  for (const TrackRow& row : truth.rows) {
    ASSERT_EQ(row.extraCells.size(), 1U);
    const bool right = row.extraCells[0] == "1";
    for (int i = 0; i < 25; ++i) {
      EXPECT_EQ(row.points(0, i) >= 322.0, right) << "frame " << row.frame << " point " << i;
    }
  }
  // The two faces move on their own trajectories: the right face is not the left one shifted.
  const Eigen::Matrix2Xd shift = truth.rows[1].points.colwise() - Eigen::Vector2d(322.0, 0.0);
  EXPECT_GT((shift - truth.rows[0].points).cwiseAbs().maxCoeff(), 0.5);
  VideoReader video(out / "sequence.avi");
  cv::Mat frame;
  ASSERT_TRUE(video.read(frame));
  EXPECT_EQ(frame.size(), cv::Size(644, 242));

  const auto alone = runClm3d(base + " --out " + (f.dir / "pair-bad").string());
  EXPECT_EQ(alone.exitCode, 2) << alone.output;
  EXPECT_TRUE(test::contains(alone.output, "--beside")) << alone.output;
  EXPECT_FALSE(fs::exists(f.dir / "pair-bad" / "truth.csv"));
}

TEST(SynthPhotoCli, BadLandmarkFilesExitOneNamingTheFile) {
  const PhotoFiles& f = photoFiles();
  const fs::path absent = f.dir / "absent.pts";
  const auto missing = runClm3d("synth --photo " + f.photo.string() + " --landmarks " +
                                absent.string() + " --out " + (f.dir / "x").string());
  EXPECT_EQ(missing.exitCode, 1) << missing.output;
  EXPECT_TRUE(test::contains(missing.output, absent.string())) << missing.output;

  const fs::path wrong = f.dir / "ten.pts";
  std::string ten = "version: 1\nn_points: 10\n{\n";
  for (int i = 0; i < 10; ++i)
    ten += std::to_string(100 + 5 * i) + " " + std::to_string(80 + i) + "\n";
  test::writeFile(wrong, ten + "}\n");
  const auto count = runClm3d("synth --photo " + f.photo.string() + " --landmarks " +
                              wrong.string() + " --out " + (f.dir / "x").string());
  EXPECT_EQ(count.exitCode, 1) << count.output;
  EXPECT_TRUE(test::contains(count.output, wrong.string())) << count.output;
  EXPECT_TRUE(test::contains(count.output, "10 points")) << count.output;

  const fs::path noPhoto = f.dir / "absent.png";
  const auto photo = runClm3d("synth --photo " + noPhoto.string() + " --landmarks " +
                              f.points.string() + " --out " + (f.dir / "x").string());
  EXPECT_EQ(photo.exitCode, 1) << photo.output;
  EXPECT_TRUE(test::contains(photo.output, noPhoto.string())) << photo.output;

  const auto both = runClm3d("synth --photo " + f.photo.string() + " --head-seed 1 --landmarks " +
                             f.points.string() + " --out " + (f.dir / "x").string());
  EXPECT_EQ(both.exitCode, 2) << both.output;
  const auto noPoints =
      runClm3d("synth --photo " + f.photo.string() + " --out " + (f.dir / "x").string());
  EXPECT_EQ(noPoints.exitCode, 2) << noPoints.output;
  EXPECT_TRUE(test::contains(noPoints.output, "--landmarks")) << noPoints.output;
  EXPECT_FALSE(fs::exists(f.dir / "x"));
}

TEST(SynthPhotoCli, AnLfpwPhotoWithItsMarkUp) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const fs::path folder = data / "photos" / "lfpw" / "test";
  if (!fs::is_directory(folder)) GTEST_SKIP() << folder << " not found";
  fs::path photo;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() == ".jpg" &&
        fs::exists(fs::path(entry.path()).replace_extension(".pts")) &&
        (photo.empty() || entry.path() < photo)) {
      photo = entry.path();
    }
  }
  ASSERT_FALSE(photo.empty());
  const test::TempDir dir;
  const auto result = runClm3d("synth --photo " + photo.string() + " --landmarks " +
                               fs::path(photo).replace_extension(".pts").string() +
                               " --frames 5 --out " + (dir / "lfpw").string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const TrackTable truth = readTrackTable(dir / "lfpw" / "truth.csv");
  EXPECT_EQ(truth.rows.size(), 5U);
  EXPECT_EQ(truth.landmarkCount, 25);
}

}  // namespace
}  // namespace clm3d
