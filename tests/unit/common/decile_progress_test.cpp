// DecileProgress: each tenth reported once, in order, and never from two threads at once, when many
// workers report at the same time (the demo's training progress raced on its counter before).
#include "core/common/decile_progress.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "core/common/parallel_for.hpp"

namespace clm3d {
namespace {

TEST(DecileProgress, ReportsEachTenthOnceInOrder) {
  std::vector<int> seen;
  DecileProgress progress([&](int percent, std::string_view) { seen.push_back(percent); }, true);
  for (double f : {0.0, 0.01, 0.05, 0.1, 0.1, 0.34, 0.2, 0.999, 1.0, 1.0}) progress(f, "stage");
  EXPECT_EQ(seen, (std::vector<int>{0, 10, 30, 90, 100}));
}

TEST(DecileProgress, WorkersReportingAtOnceNeverOverlapNorRepeat) {
  std::vector<int> seen;
  std::atomic<int> inside{0};
  std::atomic<int> overlaps{0};
  DecileProgress progress([&](int percent, std::string_view) {
    if (inside.fetch_add(1) != 0) ++overlaps;
    seen.push_back(percent);  // unsynchronised on purpose: the lock must protect it
    std::this_thread::yield();
    inside.fetch_sub(1);
  });
  const ProgressCallback callback = progress.callback();
  constexpr int kSteps = 4000;
  std::atomic<int> done{0};
  parallelFor(kSteps, 8, [&](int) {
    const int finished = ++done;
    callback(static_cast<double>(finished) / kSteps, "work");
  });
  EXPECT_EQ(overlaps.load(), 0);
  // Workers may reach their tenths out of order (one skipped), never twice or backwards.
  ASSERT_FALSE(seen.empty());
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_LT(seen[i - 1], seen[i]);
  EXPECT_EQ(seen.back(), 100);
}

}  // namespace
}  // namespace clm3d
