#include "core/video/frame_prefetcher.hpp"

#include <algorithm>
#include <utility>

#include "core/video/video_reader.hpp"

namespace clm3d {

FramePrefetcher::FramePrefetcher(Source source, int capacity)
    : source_(std::move(source)), ring_(static_cast<std::size_t>(std::max(2, capacity))) {
  thread_ = std::thread([this] { run(); });
}

FramePrefetcher::FramePrefetcher(VideoReader& reader, int capacity)
    : FramePrefetcher(
          [&reader](DecodedFrame& frame) {
            if (!reader.readInto(frame.image)) return false;
            frame.index = reader.frameIndex();
            frame.timestamp = reader.timestamp();
            frame.skippedBefore = reader.skippedBefore();
            return true;
          },
          capacity) {}

FramePrefetcher::~FramePrefetcher() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  freed_.notify_all();
  thread_.join();
}

void FramePrefetcher::run() {
  const std::size_t capacity = ring_.size();
  while (true) {
    std::size_t slot = 0;
    {
      std::unique_lock lock(mutex_);
      freed_.wait(lock, [&] { return stop_ || count_ < capacity; });
      if (stop_) break;
      slot = (head_ + count_) % capacity;  // beyond count_: the caller never looks at it
    }
    bool more = false;
    std::exception_ptr error;
    try {
      more = source_(ring_[slot]);
    } catch (...) {
      error = std::current_exception();
    }
    {
      const std::lock_guard lock(mutex_);
      if (more) {
        ++count_;
      } else {
        finished_ = true;
        error_ = std::move(error);
      }
    }
    filled_.notify_one();
    if (!more) return;
  }
  const std::lock_guard lock(mutex_);
  finished_ = true;
}

const DecodedFrame* FramePrefetcher::next() {
  std::unique_lock lock(mutex_);
  if (holding_) {
    DecodedFrame& done = ring_[head_];
    // A buffer the caller kept a copy of is the caller's now: the decoder makes a new one rather
    // than overwrite pixels someone may still read.
    if (done.image.u != nullptr && done.image.u->refcount > 1) done.image = cv::Mat();
    head_ = (head_ + 1) % ring_.size();
    --count_;
    holding_ = false;
    freed_.notify_one();
  }
  filled_.wait(lock, [&] { return count_ > 0 || finished_; });
  if (count_ > 0) {
    holding_ = true;
    return &ring_[head_];
  }
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  return nullptr;
}

}  // namespace clm3d
