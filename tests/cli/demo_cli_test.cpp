// clm3d demo end to end at a small size: heads, renders, training, the held-out test sequence,
// tracking with the overlay, and the evaluation whose summary ends the output.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

TEST(DemoCli, RunsTheWholeChainAndEndsWithTheErrorSummary) {
  test::TempDir dir;
  const auto result = test::runClm3d(
      "demo --heads 2 --samples 1 --size 64 --sequence-step 15 --out " + (dir / "demo").string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const char* file : {"model.clm3d", "tracks.csv", "overlay.mp4", "sequence/truth.csv",
                           "eval/report.json", "eval/cdf.png", "training-views.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "demo" / file)) << file;
  }
  const auto summary = result.output.find("error: mean");
  ASSERT_NE(summary, std::string::npos) << result.output;
  EXPECT_NE(result.output.find("overlay video:", summary), std::string::npos) << result.output;
}

}  // namespace
}  // namespace clm3d
