// A ProgressCallback that passes on only each new tenth of the work, for command-line progress
// lines: training and rendering call progress from worker threads, so the counter is kept under a
// lock and the report function never runs on two threads at once (progress.hpp requires callbacks
// to be thread-safe; the demo's first copy of this updated its counter without a lock).
#pragma once

#include <functional>
#include <mutex>
#include <string>
#include <string_view>

#include "core/common/progress.hpp"

namespace clm3d {

class DecileProgress {
 public:
  // report(percent, stage) runs once per tenth reached (10, 20, ... 100; 0 as well when
  // reportStart), in increasing order, one call at a time, on whichever thread reached it.
  explicit DecileProgress(std::function<void(int percent, std::string_view stage)> report,
                          bool reportStart = false);

  void operator()(double fraction, std::string_view stage);
  // A callback for core functions; `this` must outlive its use.
  ProgressCallback callback();

 private:
  std::function<void(int, std::string_view)> report_;
  std::mutex mutex_;
  int lastDecile_;
};

}  // namespace clm3d
