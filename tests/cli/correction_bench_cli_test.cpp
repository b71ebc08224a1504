// clm3d correction-bench through the real binary, on the fixture model and a 7-frame video of the
// held-out procedural head with its exact truth: with a tolerance the tiny model cannot reach,
// every strategy corrects up to the cap and says so, review-adapt adapts and compares the frames it
// never corrected, and the CSV has a row per strategy; videos and truths that do not pair, an
// unknown strategy and a truth of another landmark count are refused.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "core/track/track_table.hpp"
#include "tests/support/held_out_sequence.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::quoted;
using test::runClm3d;

using BenchInputs = test::HeldOutInputs;
constexpr auto writeBenchInputs = test::writeHeldOutInputs;

std::string benchCommand(const BenchInputs& inputs, const std::string& more) {
  return "correction-bench --model " + quoted(inputs.model) + " --video " + quoted(inputs.video) +
         " --truth " + quoted(inputs.truth) + " --label head " + more + " --quiet";
}

TEST(CorrectionBenchCli, EveryStrategyRunsToTheCapAndTheCsvHasItsRows) {
  const test::TempDir dir;
  const BenchInputs inputs = writeBenchInputs(dir.path());
  const auto csv = dir / "bench.csv";
  const auto result = runClm3d(benchCommand(
      inputs,
      "--tolerance 0.001 --max-corrections 2 --adapt-every 1 --jitter 1 --csv " + quoted(csv)));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const std::string strategy : {"in-order", "review", "review-adapt"}) {
    EXPECT_TRUE(test::contains(result.output, "| " + strategy + " | 2 (capped) |"))
        << strategy << "\n"
        << result.output;
  }
  EXPECT_TRUE(test::contains(result.output, "review-adapt / in-order frames corrected: 2 / 2"))
      << result.output;
  EXPECT_TRUE(test::contains(result.output, "| head | 5 | 2 |"))
      << result.output;  // never corrected

  std::istringstream rows(test::readFile(csv));
  std::string line;
  std::getline(rows, line);
  EXPECT_EQ(line.rfind("sequence,frames,scored,start_error,strategy,", 0), 0u) << line;
  int count = 0;
  while (std::getline(rows, line)) {
    ++count;
    EXPECT_EQ(line.rfind("head,7,7,", 0), 0u) << line;
    EXPECT_TRUE(test::contains(line, ",2,")) << line;
  }
  EXPECT_EQ(count, 3);
}

TEST(CorrectionBenchCli, InputsThatDoNotPairOrFitAreRefused) {
  const test::TempDir dir;
  const BenchInputs inputs = writeBenchInputs(dir.path());
  EXPECT_EQ(runClm3d(benchCommand(inputs, "--truth " + quoted(inputs.truth))).exitCode, 2);
  EXPECT_EQ(runClm3d(benchCommand(inputs, "--strategies in-order,random")).exitCode, 2);

  TrackTable five = inputs.table;
  five.landmarkCount = 5;
  for (TrackRow& row : five.rows) row.points.conservativeResize(2, 5);
  const auto fivePoints = dir / "five.csv";
  writeTrackTable(fivePoints, five);
  BenchInputs wrong = inputs;
  wrong.truth = fivePoints;
  const auto result = runClm3d(benchCommand(wrong, "--strategies in-order"));
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_TRUE(test::contains(result.output, fivePoints.string() + ": has 5 landmarks"))
      << result.output;
}

}  // namespace
}  // namespace clm3d
