// The worker pool: every index runs exactly once whatever the thread count, the first exception
// reaches the caller after the workers joined, a cancelled token stops the workers taking indices
// and reaches the caller as Cancelled, and an empty range runs nothing.
#include "core/common/parallel_for.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace clm3d {
namespace {

TEST(ParallelFor, EveryIndexOnceForAnyThreadCount) {
  for (const int threads : {0, 1, 2, 7}) {
    std::vector<std::atomic<int>> runs(100);
    parallelFor(100, threads, [&](int i) { ++runs[static_cast<std::size_t>(i)]; });
    for (const auto& count : runs) EXPECT_EQ(count.load(), 1) << threads << " threads";
  }
  EXPECT_EQ(workerCount(3, 8), 3);
  EXPECT_EQ(workerCount(0, 8), 1);
  EXPECT_GE(workerCount(100, 0), 1);
}

TEST(ParallelFor, TheFirstExceptionReachesTheCaller) {
  const auto failAt10 = [](std::atomic<int>& ran) {
    return [&ran](int i) {
      ++ran;
      if (i == 10) throw std::runtime_error("body 10 failed");
    };
  };
  std::atomic<int> two{0};
  EXPECT_THROW(parallelFor(1000, 2, failAt10(two)), std::runtime_error);
  std::atomic<int> one{0};
  EXPECT_THROW(parallelFor(1000, 1, failAt10(one)), std::runtime_error);
  EXPECT_EQ(one.load(), 11);  // no index is taken after the failure
}

TEST(ParallelFor, CancellingStopsTakingIndicesAndThrowsCancelled) {
  for (const int threads : {1, 2}) {
    CancelToken cancel;
    std::atomic<int> ran{0};
    EXPECT_THROW(parallelFor(
                     1000, threads,
                     [&](int i) {
                       ++ran;
                       if (i == 10) cancel.cancel();
                     },
                     &cancel),
                 Cancelled);
    // Indices already taken when the token fired still run, one per worker at most.
    EXPECT_LE(ran.load(), 11 + threads) << threads << " threads";
  }
  // A body's own exception wins over the cancellation it raced with.
  CancelToken cancel;
  EXPECT_THROW(parallelFor(
                   100, 1,
                   [&](int) {
                     cancel.cancel();
                     throw std::runtime_error("body failed");
                   },
                   &cancel),
               std::runtime_error);
  // A token that never fires changes nothing.
  CancelToken idle;
  std::atomic<int> all{0};
  parallelFor(
      100, 2, [&](int) { ++all; }, &idle);
  EXPECT_EQ(all.load(), 100);
}

TEST(ParallelFor, AnEmptyRangeRunsNothing) {
  bool ran = false;
  parallelFor(0, 2, [&](int) { ran = true; });
  EXPECT_FALSE(ran);
}

}  // namespace
}  // namespace clm3d
