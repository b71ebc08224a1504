// Frames a video declares but cannot give: a truncated file (the container's frame count is more
// than can be decoded) and a stretch of damaged bytes in the middle (FFmpeg skips the frames it
// cannot decode: VideoReader counts them from the presentation times, so every later frame keeps
// its place). Intact videos of every format never report one.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/core.hpp>
#include <set>
#include <string>

#include "core/video/video_reader.hpp"
#include "core/video/video_writer.hpp"
#include "tests/support/test_support.hpp"
#include "tests/unit/video/damaged_video.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

TEST(UnreadableFrames, ATruncatedFileDeclaresMoreFramesThanItGives) {
  const test::TempDir dir;
  const fs::path whole = dir / "whole.avi";
  test::writeNumberedVideo(whole, 30);
  const fs::path cut = dir / "cut.avi";
  test::writeTruncatedCopy(whole, cut, 0.6);
  VideoReader reader(cut);
  EXPECT_EQ(reader.frameCount(), 30);  // the header still says 30
  cv::Mat frame;
  int decoded = 0;
  while (reader.read(frame)) {
    EXPECT_EQ(reader.frameIndex(), decoded);
    EXPECT_EQ(reader.skippedBefore(), 0);
    EXPECT_EQ(test::numberOf(frame), decoded);
    ++decoded;
  }
  EXPECT_GT(decoded, 5);
  EXPECT_LT(decoded, 25);
}

TEST(UnreadableFrames, DamagedFramesInTheMiddleAreCountedAndTheRestKeepTheirPlace) {
  const test::TempDir dir;
  const fs::path whole = dir / "whole.mkv";
  test::writeNumberedVideo(whole, 30);
  const fs::path damaged = dir / "damaged.mkv";
  test::writeDamagedCopy(whole, damaged, 0.5, 3000);
  VideoReader reader(damaged);
  EXPECT_EQ(reader.frameCount(), 30);
  cv::Mat frame;
  int decoded = 0;
  int skipped = 0;
  int last = -1;
  while (reader.read(frame)) {
    ++decoded;
    skipped += reader.skippedBefore();
    EXPECT_EQ(reader.frameIndex(), last + 1 + reader.skippedBefore());
    // The frame's own pixels say which frame it is: the index is its place in the video.
    EXPECT_EQ(test::numberOf(frame), reader.frameIndex());
    EXPECT_NEAR(reader.timestamp(), reader.frameIndex() / 25.0, 1e-6);
    last = reader.frameIndex();
  }
  EXPECT_GT(skipped, 0);
  EXPECT_EQ(last, 29);
  EXPECT_EQ(decoded + skipped, 30);
}

TEST(UnreadableFrames, IntactVideosSkipNothing) {
  const test::TempDir dir;
  for (const char* name : {"clip.avi", "clip.mkv", "clip.mp4"}) {
    const fs::path path = dir / name;
    test::writeNumberedVideo(path, 30);
    VideoReader reader(path);
    cv::Mat frame;
    int decoded = 0;
    while (reader.readInto(frame)) {
      EXPECT_EQ(reader.skippedBefore(), 0) << name;
      EXPECT_EQ(reader.frameIndex(), decoded) << name;
      ++decoded;
    }
    EXPECT_EQ(decoded, 30) << name;
    EXPECT_EQ(reader.frameCount(), 30) << name;
  }
}

TEST(UnreadableFrames, ReadIntoReusesTheCallersBuffer) {
  const test::TempDir dir;
  const fs::path path = dir / "clip.avi";
  test::writeNumberedVideo(path, 6);
  VideoReader reader(path);
  cv::Mat a;
  cv::Mat b;
  ASSERT_TRUE(reader.readInto(a));
  ASSERT_TRUE(reader.readInto(b));
  std::set<const uchar*> buffers;
  for (int i = 0; i < 4; ++i) {
    cv::Mat& frame = i % 2 == 0 ? a : b;
    ASSERT_TRUE(reader.readInto(frame));
    buffers.insert(frame.data);
  }
  EXPECT_LE(buffers.size(), 3U);  // two buffers and the reader's own, handed round
}

}  // namespace
}  // namespace clm3d
