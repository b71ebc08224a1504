// Decoded frames of the open video for the frame view and the player, on the GUI thread: the next
// frame is read straight on (playback and stepping forward cost one decode), any other frame is a
// seek; the last frame decoded is kept, so redrawing it (a drag, the patch checkbox) decodes
// nothing. The page measures decode times (lastDecodeMs) to show they stay far below a stall.
#pragma once

#include <filesystem>
#include <memory>
#include <opencv2/core/mat.hpp>

namespace clm3d {
class VideoReader;
}

namespace clm3d::ui {

class FrameSource {
 public:
  FrameSource();
  ~FrameSource();
  FrameSource(const FrameSource&) = delete;
  FrameSource& operator=(const FrameSource&) = delete;

  // InputError naming the file if it is not a readable video.
  void open(const std::filesystem::path& video);
  void close();
  bool isOpen() const { return reader_ != nullptr; }

  // The frame (BGR); empty if it is outside the video or cannot be decoded.
  const cv::Mat& frame(int index);
  double lastDecodeMs() const { return lastDecodeMs_; }
  double longestDecodeMs() const { return longestDecodeMs_; }

 private:
  std::unique_ptr<VideoReader> reader_;
  cv::Mat current_;
  int currentIndex_ = -1;
  double lastDecodeMs_ = 0.0;
  double longestDecodeMs_ = 0.0;
};

}  // namespace clm3d::ui
