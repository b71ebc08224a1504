#include "ui/track/frame_source.hpp"

#include <algorithm>
#include <chrono>

#include "core/video/video_reader.hpp"

namespace clm3d::ui {

FrameSource::FrameSource() = default;
FrameSource::~FrameSource() = default;

void FrameSource::open(const std::filesystem::path& video) {
  auto reader = std::make_unique<VideoReader>(video);
  reader_ = std::move(reader);
  current_.release();
  currentIndex_ = -1;
}

void FrameSource::close() {
  reader_.reset();
  current_.release();
  currentIndex_ = -1;
}

const cv::Mat& FrameSource::frame(int index) {
  if (!reader_ || index == currentIndex_) return current_;
  const auto begin = std::chrono::steady_clock::now();
  current_.release();
  currentIndex_ = -1;
  const bool next = index == reader_->frameIndex() + 1;
  if ((next || reader_->seek(index)) && reader_->read(current_)) currentIndex_ = index;
  lastDecodeMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
  longestDecodeMs_ = std::max(longestDecodeMs_, lastDecodeMs_);
  return current_;
}

}  // namespace clm3d::ui
