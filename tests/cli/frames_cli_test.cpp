// clm3d frames through the real binary: a lossless video's frames come out as numbered images,
// the count is reported, progress is one meter line (app/commands/cli_progress), and a missing
// video exits 1 naming the file.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <string>

#include "core/video/video_writer.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::runClm3d;

// A lossless 32x24 video of `frames` grey frames, each a different shade.
void writeGreyVideo(const std::filesystem::path& video, int frames, int step) {
  VideoWriter writer(video, 32, 24, 25.0);
  for (int i = 0; i < frames; ++i)
    writer.write(cv::Mat(24, 32, CV_8UC3, cv::Scalar::all(step * i)));
  writer.close();
}

TEST(FramesCli, WritesEveryNthFrame) {
  test::TempDir dir;
  const auto video = dir / "v.avi";
  writeGreyVideo(video, 7, 30);
  const auto result = runClm3d("frames --video " + video.string() + " --out " +
                               (dir / "frames").string() + " --every 2 --format jpg --quiet");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("wrote 4 of 7 frames"), std::string::npos) << result.output;
  for (const char* name :
       {"frame_000000.jpg", "frame_000002.jpg", "frame_000004.jpg", "frame_000006.jpg"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "frames" / name)) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "frames" / "frame_000001.jpg"));
}

TEST(FramesCli, ProgressIsOneMeterLineEndedOnce) {
  test::TempDir dir;
  const auto video = dir / "v.avi";
  writeGreyVideo(video, 3, 60);
  const auto result =
      runClm3d("frames --video " + video.string() + " --out " + (dir / "frames").string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  // Redrawn in place (carriage returns), 100% said once, then a line break before the summary.
  const auto done = result.output.find("exporting frames: 100.0%\n");
  ASSERT_NE(done, std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("100.0%", done + 24), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("100.0%"), done + 18) << result.output;
  EXPECT_EQ(result.output.find('\r'), 0u) << result.output;
}

TEST(FramesCli, AMissingVideoExits1NamingIt) {
  test::TempDir dir;
  const auto result = runClm3d("frames --video " + (dir / "nothing.mp4").string() + " --out " +
                               (dir / "frames").string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("nothing.mp4"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace clm3d
