// JobProgress: jobs finished on many threads at once are reported one at a time, every share
// higher than the one before and the last at the end of the range; an increment made apart from
// its report let the demo's render progress go back (one run in fifteen under ctest -j2).
#include "core/common/job_progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "core/common/parallel_for.hpp"

namespace clm3d {
namespace {

TEST(JobProgress, WorkersFinishingAtOnceReportRisingSharesOneAtATime) {
  constexpr int kJobs = 2000;
  std::vector<double> seen;
  std::vector<std::string> stages;
  std::atomic<int> inside{0};
  std::atomic<int> overlaps{0};
  const ProgressCallback callback = [&](double fraction, std::string_view stage) {
    if (inside.fetch_add(1) != 0) ++overlaps;
    seen.push_back(fraction);  // unsynchronised on purpose: the lock must protect it
    stages.emplace_back(stage);
    std::this_thread::yield();
    inside.fetch_sub(1);
  };
  JobProgress progress(callback, kJobs, "rendering", 0.2, 0.8);
  std::atomic<int> counted{0};
  parallelFor(kJobs, 4, [&](int) {
    if (progress.finished() == kJobs) ++counted;
  });
  EXPECT_EQ(overlaps.load(), 0);
  ASSERT_EQ(seen.size(), static_cast<std::size_t>(kJobs));
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(std::adjacent_find(seen.begin(), seen.end()), seen.end());  // strictly rising
  EXPECT_DOUBLE_EQ(seen.front(), 0.2 + 0.6 / kJobs);
  EXPECT_DOUBLE_EQ(seen.back(), 0.8);
  EXPECT_EQ(counted.load(), 1);  // exactly one worker finished the last job
  EXPECT_EQ(std::count(stages.begin(), stages.end(), "rendering"), kJobs);
}

TEST(JobProgress, NoCallbackCountsAndExtraJobsStayAtTheEnd) {
  const ProgressCallback none;
  JobProgress silent(none, 3, "x");
  EXPECT_EQ(silent.finished(), 1);
  EXPECT_EQ(silent.finished(), 2);

  std::vector<double> seen;
  const ProgressCallback callback = [&](double fraction, std::string_view) {
    seen.push_back(fraction);
  };
  JobProgress progress(callback, 2, "x");
  for (int i = 0; i < 3; ++i) progress.finished();
  EXPECT_EQ(seen, (std::vector<double>{0.5, 1.0, 1.0}));
}

}  // namespace
}  // namespace clm3d
