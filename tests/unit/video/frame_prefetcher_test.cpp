// FramePrefetcher: the decoder thread hands frames over in order, reuses its buffers, rethrows a
// decode error on the caller's thread after the frames before it, and stops cleanly when the
// caller goes away early (cancel) even while the decoder is blocked on a full ring. These run
// under ThreadSanitizer in CI (tests/CMakeLists.txt, tsan.video).
#include "core/video/frame_prefetcher.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <opencv2/core.hpp>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/progress.hpp"
#include "core/video/video_reader.hpp"
#include "core/video/video_writer.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// A source of `count` frames whose pixels all hold the frame's index (mod 256), slowed by `delay`.
FramePrefetcher::Source countingSource(int count, std::atomic<int>& produced,
                                       std::chrono::microseconds delay = {}) {
  return [count, &produced, delay](DecodedFrame& frame) {
    const int index = produced.load();
    if (index >= count) return false;
    if (delay.count() > 0) std::this_thread::sleep_for(delay);
    frame.image.create(8, 12, CV_8UC3);
    frame.image.setTo(cv::Scalar::all(index % 256));
    frame.index = index;
    frame.timestamp = index / 25.0;
    produced.store(index + 1);
    return true;
  };
}

TEST(FramePrefetcher, HandsFramesOverInOrder) {
  std::atomic<int> produced{0};
  FramePrefetcher frames(countingSource(300, produced));
  int expected = 0;
  while (const DecodedFrame* frame = frames.next()) {
    ASSERT_EQ(frame->index, expected);
    ASSERT_EQ(frame->image.at<cv::Vec3b>(3, 5)[0], expected % 256);
    ++expected;
    if (expected % 7 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  EXPECT_EQ(expected, 300);
  EXPECT_EQ(frames.next(), nullptr);  // stays at the end
}

TEST(FramePrefetcher, ReusesARingOfBuffers) {
  std::atomic<int> produced{0};
  std::set<const uchar*> buffers;
  {
    FramePrefetcher frames(countingSource(64, produced), 3);
    while (const DecodedFrame* frame = frames.next()) buffers.insert(frame->image.data);
  }
  EXPECT_LE(buffers.size(), 3U);  // one per slot, none per frame
}

TEST(FramePrefetcher, AFrameTheCallerKeepsIsNotOverwritten) {
  std::atomic<int> produced{0};
  FramePrefetcher frames(countingSource(40, produced), 2);
  const DecodedFrame* first = frames.next();
  ASSERT_NE(first, nullptr);
  const cv::Mat kept = first->image;  // shares the slot's buffer
  while (frames.next() != nullptr) {
  }
  EXPECT_EQ(kept.at<cv::Vec3b>(0, 0)[0], 0);
}

TEST(FramePrefetcher, ADecodeErrorReachesTheCallerAfterTheFramesBeforeIt) {
  std::atomic<int> produced{0};
  auto good = countingSource(1000, produced);
  FramePrefetcher frames([&](DecodedFrame& frame) {
    if (produced.load() == 17) throw InputError("clip.mp4: frame 17 cannot be decoded");
    return good(frame);
  });
  int seen = 0;
  try {
    while (const DecodedFrame* frame = frames.next()) {
      EXPECT_EQ(frame->index, seen);
      ++seen;
    }
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "clip.mp4: frame 17 cannot be decoded");
  }
  EXPECT_EQ(seen, 17);
  EXPECT_EQ(frames.next(), nullptr);  // the error is reported once; the decoder has stopped
}

TEST(FramePrefetcher, LeavingEarlyStopsTheDecoderWhileItWaitsForRoom) {
  std::atomic<int> produced{0};
  const auto begin = std::chrono::steady_clock::now();
  {
    // An endless source: the decoder fills the ring and waits; the caller takes two frames and
    // leaves, as a cancelled track does (its Cancelled exception unwinds through here).
    FramePrefetcher frames(countingSource(1 << 30, produced));
    ASSERT_NE(frames.next(), nullptr);
    ASSERT_NE(frames.next(), nullptr);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_LE(produced.load(), FramePrefetcher::kDefaultCapacity + 1);  // bounded
  }
  EXPECT_LT(std::chrono::steady_clock::now() - begin, std::chrono::seconds(5));
}

TEST(FramePrefetcher, CancelInTheMiddleOfASlowDecodeDoesNotHang) {
  std::atomic<int> produced{0};
  CancelToken cancel;
  int seen = 0;
  try {
    FramePrefetcher frames(countingSource(1 << 30, produced, std::chrono::milliseconds(2)));
    while (frames.next() != nullptr) {
      if (++seen == 5) cancel.cancel();
      cancel.throwIfCancelled();
    }
  } catch (const Cancelled&) {
  }
  EXPECT_EQ(seen, 5);
}

// With a real video: the same frames, in the same order, as reading it directly.
TEST(FramePrefetcher, ReadsAVideoAsTheReaderDoes) {
  const test::TempDir dir;
  const auto path = dir / "clip.avi";
  {
    VideoWriter writer(path, 32, 24, 25.0);
    for (int i = 0; i < 30; ++i) {
      cv::Mat frame(24, 32, CV_8UC3, cv::Scalar(i * 8, 255 - i * 8, (i * 37) % 256));
      writer.write(frame);
    }
    writer.close();
  }
  VideoReader direct(path);
  VideoReader ahead(path);
  FramePrefetcher frames(ahead);
  cv::Mat expected;
  int count = 0;
  while (const DecodedFrame* frame = frames.next()) {
    ASSERT_TRUE(direct.read(expected));
    EXPECT_EQ(frame->index, direct.frameIndex());
    EXPECT_DOUBLE_EQ(frame->timestamp, direct.timestamp());
    EXPECT_EQ(frame->skippedBefore, 0);
    EXPECT_EQ(cv::norm(frame->image, expected, cv::NORM_INF), 0.0);
    ++count;
  }
  EXPECT_FALSE(direct.read(expected));
  EXPECT_EQ(count, 30);
}

}  // namespace
}  // namespace clm3d
