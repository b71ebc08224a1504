// Decoding a video on its own thread while the caller works on the frames it has (the tracker's
// fit): a decoder thread fills a small ring of frame buffers ahead of the caller, in frame order.
// The buffers are reused, so nothing is allocated per frame once the ring is warm; a decode error
// stops the thread and is rethrown on the caller's thread after the frames decoded before it; the
// destructor stops and joins the thread (a caller that throws, e.g. Cancelled, simply lets it go).
// The source (a VideoReader) belongs to the decoder thread while the prefetcher lives: the caller
// must keep it alive and not touch it until next() has returned nullptr or the prefetcher is gone.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <opencv2/core/mat.hpp>
#include <thread>
#include <vector>

namespace clm3d {

class VideoReader;

// One decoded frame as VideoReader reports it.
struct DecodedFrame {
  cv::Mat image;           // 8-bit BGR; the ring's buffer, overwritten once handed back
  int index = -1;          // VideoReader::frameIndex()
  double timestamp = 0.0;  // VideoReader::timestamp()
  int skippedBefore = 0;   // VideoReader::skippedBefore(): unreadable frames just before this one
};

class FramePrefetcher {
 public:
  // Fills the frame (reusing its image buffer); false at the end. May throw: the exception reaches
  // the caller through next(). Called on the decoder thread only.
  using Source = std::function<bool(DecodedFrame&)>;

  // capacity: frames decoded ahead, the one the caller holds included (at least 2).
  explicit FramePrefetcher(Source source, int capacity = kDefaultCapacity);
  // Reads `reader` from where it stands (VideoReader::readInto).
  explicit FramePrefetcher(VideoReader& reader, int capacity = kDefaultCapacity);
  ~FramePrefetcher();
  FramePrefetcher(const FramePrefetcher&) = delete;
  FramePrefetcher& operator=(const FramePrefetcher&) = delete;

  // The next frame in order, valid until the next call or the prefetcher's end; nullptr at the end
  // of the source. Hands the previous frame's buffer back to the decoder (a buffer the caller still
  // shares, a cv::Mat copy kept somewhere, is left to the caller and a new one made). Rethrows the
  // source's exception once the frames before it have been handed out.
  const DecodedFrame* next();

  static constexpr int kDefaultCapacity = 4;

 private:
  void run();

  Source source_;
  std::vector<DecodedFrame> ring_;
  std::mutex mutex_;
  std::condition_variable filled_;  // a frame was decoded, or the decoder finished
  std::condition_variable freed_;   // a slot was handed back, or stop was asked for
  std::size_t head_ = 0;            // the oldest decoded slot (the one next() hands out)
  std::size_t count_ = 0;           // decoded slots not yet handed back (the held one included)
  bool holding_ = false;            // the caller holds ring_[head_]
  bool finished_ = false;           // the decoder has stopped (end of source or error)
  bool stop_ = false;               // the prefetcher is going away
  std::exception_ptr error_;
  std::thread thread_;  // last: started when everything above exists
};

}  // namespace clm3d
