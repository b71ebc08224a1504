// exportFrames: the selected frames of a lossless video come out as images named by frame index,
// holding exactly those frames; bad settings and unreadable videos are errors naming the problem.
#include "core/track/frame_export.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "core/common/error.hpp"
#include "core/track/ground_truth.hpp"
#include "core/video/video_writer.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// Frame i is filled with grey 20 * i + 5, so a written image says which frame it holds.
std::filesystem::path writeNumberedVideo(const std::filesystem::path& folder, int frames) {
  const auto path = folder / "numbered.avi";
  VideoWriter writer(path, 64, 48, 25.0);
  for (int i = 0; i < frames; ++i) {
    writer.write(cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(20 * i + 5)));
  }
  writer.close();
  return path;
}

TEST(FrameExport, WritesTheSelectedFramesByIndex) {
  test::TempDir dir;
  const auto video = writeNumberedVideo(dir.path(), 12);
  FrameExportSettings settings;
  settings.every = 3;
  settings.first = 2;
  settings.last = 9;
  double lastProgress = 0.0;
  const FrameExportSummary summary = exportFrames(
      video, dir / "frames", settings, [&](double f, std::string_view) { lastProgress = f; });
  EXPECT_EQ(summary.written, 3);  // frames 2, 5, 8
  EXPECT_EQ(lastProgress, 1.0);
  for (const int frame : {2, 5, 8}) {
    const auto file = dir / "frames" / frameFileName(frame, ".png");
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const cv::Mat image = readImage(file);
    EXPECT_EQ(image.at<cv::Vec3b>(10, 10)[1], 20 * frame + 5) << frame;
  }
  for (const int frame : {0, 1, 3, 9, 11}) {
    EXPECT_FALSE(std::filesystem::exists(dir / "frames" / frameFileName(frame, ".png"))) << frame;
  }
}

TEST(FrameExport, NamesPairWithTheGroundTruthPts) {
  EXPECT_EQ(frameFileName(42, ".png").string(), "frame_000042.png");
  EXPECT_EQ(groundTruthPtsName(42).stem(), frameFileName(42, ".png").stem());
}

TEST(FrameExport, RejectsBadSettingsAndUnreadableVideos) {
  test::TempDir dir;
  const auto video = writeNumberedVideo(dir.path(), 4);
  FrameExportSettings every0;
  every0.every = 0;
  EXPECT_THROW(exportFrames(video, dir / "a", every0), InputError);
  FrameExportSettings backwards;
  backwards.first = 3;
  backwards.last = 1;
  EXPECT_THROW(exportFrames(video, dir / "a", backwards), InputError);
  FrameExportSettings beyond;
  beyond.first = 40;
  EXPECT_THROW(exportFrames(video, dir / "a", beyond), InputError);
  FrameExportSettings gif;
  gif.extension = ".gif";
  EXPECT_THROW(exportFrames(video, dir / "a", gif), InputError);
  try {
    exportFrames(dir / "missing.avi", dir / "a", {});
    FAIL() << "no error for a missing video";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("missing.avi"), std::string::npos) << error.what();
  }
}

TEST(FrameExport, StopsWhenCancelledKeepingWhatItWrote) {
  test::TempDir dir;
  const auto video = writeNumberedVideo(dir.path(), 6);
  CancelToken cancel;
  int calls = 0;
  EXPECT_THROW(exportFrames(
                   video, dir / "frames", {},
                   [&](double, std::string_view) {
                     if (++calls == 2) cancel.cancel();
                   },
                   &cancel),
               Cancelled);
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / frameFileName(0, ".png")));
  EXPECT_FALSE(std::filesystem::exists(dir / "frames" / frameFileName(5, ".png")));
}

}  // namespace
}  // namespace clm3d
