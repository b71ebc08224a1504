// clm3d track through the real binary on a video cut short (issue 27 item 5): it tracks the frames
// it can read, warns naming the file and the counts, lists the skipped frames in its summary and
// marks them in the tracks CSV's status column.
#include <gtest/gtest.h>

#include <string>

#include "core/model/model_file.hpp"
#include "core/track/track_table.hpp"
#include "tests/support/test_support.hpp"
#include "tests/support/tiny_model.hpp"
#include "tests/unit/video/damaged_video.hpp"

namespace clm3d {
namespace {

TEST(TrackCli, AVideoCutShortIsTrackedWithAWarningAndItsMissingFramesMarked) {
  const test::TempDir dir;
  const std::string model = (dir / "tiny.clm3d").string();
  saveModel(test::makeTinyModel(), model);
  test::writeNumberedVideo(dir / "whole.avi", 30);
  const auto cut = dir / "cut.avi";
  test::writeTruncatedCopy(dir / "whole.avi", cut, 0.6);
  const std::string tracks = (dir / "tracks.csv").string();
  const auto result =
      runClm3d("track --quiet --model " + model + " --video " + cut.string() + " --out " + tracks);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const TrackTable table = readTrackTable(tracks);
  ASSERT_EQ(table.rows.size(), 30U);
  int decoded = 0;
  while (decoded < 30 && !table.rows[static_cast<std::size_t>(decoded)].unreadable) ++decoded;
  ASSERT_GT(decoded, 5);
  ASSERT_LT(decoded, 25);
  for (int f = decoded; f < 30; ++f)
    EXPECT_TRUE(table.rows[static_cast<std::size_t>(f)].unreadable);
  const std::string span = std::to_string(decoded) + "-29";
  EXPECT_NE(result.output.find("warning: " + cut.string() +
                               ": the container declares 30 frames but " + std::to_string(decoded) +
                               " could be decoded; frames " + span + " are unreadable"),
            std::string::npos)
      << result.output;
  EXPECT_NE(
      result.output.find("skipped " + std::to_string(30 - decoded) + " unreadable frames: " + span),
      std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("tracked " + std::to_string(decoded) + " frames of"),
            std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace clm3d
