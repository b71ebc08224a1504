#include "core/common/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace clm3d {

int workerCount(int count, int threads) {
  const int wanted =
      threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::clamp(wanted, 1, std::max(1, count));
}

void parallelFor(int count, int threads, const std::function<void(int)>& body,
                 const CancelToken* cancel) {
  if (count <= 0) return;
  std::atomic<int> next{0};
  std::atomic<bool> stop{false};
  std::mutex errorMutex;
  std::exception_ptr error;
  const auto worker = [&] {
    for (int i = next++; i < count && !stop; i = next++) {
      if (cancel && cancel->cancelled()) {
        stop = true;
        return;
      }
      try {
        body(i);
      } catch (...) {
        const std::lock_guard lock(errorMutex);
        if (!error) error = std::current_exception();
        stop = true;
      }
    }
  };
  const int workers = workerCount(count, threads);
  if (workers == 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < workers; ++t) pool.emplace_back(worker);
    for (std::thread& thread : pool) thread.join();
  }
  if (error) std::rethrow_exception(error);
  if (cancel) cancel->throwIfCancelled();
}

}  // namespace clm3d
