// Progress reporting and cooperative cancellation for long operations (rendering batches,
// training, tracking), so the CLI can print progress and the GUI can run them on a worker thread.
#pragma once

#include <atomic>
#include <functional>
#include <string_view>

#include "core/common/error.hpp"

namespace clm3d {

// Called with the finished share of the work in [0, 1] and a short name of the current stage.
// May be called from worker threads; implementations must be thread-safe.
using ProgressCallback = std::function<void(double fraction, std::string_view stage)>;

// Set from any thread (a Cancel button, a signal handler); polled by the worker.
class CancelToken {
 public:
  void cancel() noexcept { cancelled_.store(true, std::memory_order_relaxed); }
  bool cancelled() const noexcept { return cancelled_.load(std::memory_order_relaxed); }
  // Throws Cancelled when cancel() has been called.
  void throwIfCancelled() const {
    if (cancelled()) throw Cancelled();
  }

 private:
  std::atomic<bool> cancelled_{false};
};

}  // namespace clm3d
