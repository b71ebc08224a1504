#include "core/video/video_reader.hpp"

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <system_error>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

constexpr double kFallbackFps = 30.0;

// Any decoded frame as 8-bit, 3-channel BGR.
cv::Mat toBgr(const cv::Mat& frame, const fs::path& path) {
  cv::Mat eight = frame;
  if (frame.depth() == CV_16U) {
    frame.convertTo(eight, CV_8U, 1.0 / 257.0);
  } else if (frame.depth() != CV_8U) {
    throwInputError(path, "has frames of an unsupported pixel type");
  }
  cv::Mat bgr;
  switch (eight.channels()) {
    case 3:
      bgr = eight;
      break;
    case 1:
      cv::cvtColor(eight, bgr, cv::COLOR_GRAY2BGR);
      break;
    case 4:
      cv::cvtColor(eight, bgr, cv::COLOR_BGRA2BGR);
      break;
    default:
      throwInputError(path, "has frames with " + std::to_string(eight.channels()) + " channels");
  }
  return bgr;
}

}  // namespace

struct VideoReader::Impl {
  fs::path path;
  cv::VideoCapture capture;
  double fps = kFallbackFps;
  int frameCount = -1;
  int width = 0;
  int height = 0;

  int next = 0;     // index of the frame the next decode() returns
  cv::Mat pending;  // frame `next`, already decoded (after opening), or empty
  double pendingTime = 0.0;
  int index = -1;     // last frame handed out by read()
  double time = 0.0;  // its timestamp
  double lastDecodedTime = -std::numeric_limits<double>::infinity();

  void open() {
    capture.release();
    // Exceptions from OpenCV (a corrupt file can make a backend throw) become InputErrors.
    try {
      capture.open(path.string(), cv::CAP_FFMPEG);
    } catch (const cv::Exception& e) {
      throwInputError(path, std::string("cannot be read as a video (") + e.what() + ")");
    }
    if (!capture.isOpened()) {
      throwInputError(path,
                      "cannot be read as a video (FFmpeg cannot open it: not a video, or "
                      "a format or codec this build does not support)");
    }
    next = 0;
    pending.release();
    lastDecodedTime = -std::numeric_limits<double>::infinity();
  }

  // Decodes frame `next`; false at the end.
  bool decode(cv::Mat& bgr, double& seconds) {
    cv::Mat frame;
    bool ok = false;
    try {
      ok = capture.read(frame);
    } catch (const cv::Exception& e) {
      throwInputError(path,
                      "frame " + std::to_string(next) + " cannot be decoded (" + e.what() + ")");
    }
    if (!ok || frame.empty()) return false;
    bgr = toBgr(frame, path);
    if (bgr.data == frame.data) bgr = bgr.clone();  // OpenCV reuses its buffer between reads
    const double stated = capture.get(cv::CAP_PROP_POS_MSEC) / 1000.0;
    const bool sane = std::isfinite(stated) && stated >= 0.0 &&
                      (next == 0 ? stated < 1.0 / fps + 1e-6 : stated > lastDecodedTime);
    seconds = sane ? stated : next / fps;
    if (!(seconds > lastDecodedTime)) seconds = lastDecodedTime + 1.0 / fps;
    lastDecodedTime = seconds;
    ++next;
    return true;
  }

  // Positions so that the next read returns `frame`; false if there is no such frame (the
  // position is then undefined).
  bool position(int frame) {
    if (frame == 0) {
      open();
      return true;
    }
    bool landed = false;
    try {
      landed = capture.set(cv::CAP_PROP_POS_FRAMES, frame) &&
               static_cast<int>(std::lround(capture.get(cv::CAP_PROP_POS_FRAMES))) == frame;
    } catch (const cv::Exception&) {
      landed = false;
    }
    if (landed) {
      next = frame;
      pending.release();
      lastDecodedTime = -std::numeric_limits<double>::infinity();
      return true;
    }
    // The container could not seek exactly: decode forward from the start.
    open();
    for (int i = 0; i < frame; ++i) {
      bool ok = false;
      try {
        ok = capture.grab();
      } catch (const cv::Exception&) {
        ok = false;
      }
      if (!ok) return false;
      ++next;
    }
    return true;
  }
};

VideoReader::VideoReader(const fs::path& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  std::error_code ec;
  if (!fs::exists(path, ec)) throwInputError(path, "no such file");
  if (fs::is_directory(path, ec)) throwInputError(path, "is a folder, not a video");
  impl_->open();
  const double fps = impl_->capture.get(cv::CAP_PROP_FPS);
  if (std::isfinite(fps) && fps > 0.0 && fps < 10000.0) impl_->fps = fps;
  const double count = impl_->capture.get(cv::CAP_PROP_FRAME_COUNT);
  if (std::isfinite(count) && count >= 1.0 && count < 2e9) {
    impl_->frameCount = static_cast<int>(std::lround(count));
  }
  if (!impl_->decode(impl_->pending, impl_->pendingTime)) {
    throwInputError(path, "cannot be read as a video (no frame can be decoded)");
  }
  impl_->width = impl_->pending.cols;
  impl_->height = impl_->pending.rows;
  impl_->next = 0;  // the pending frame is frame 0
}

VideoReader::~VideoReader() = default;
VideoReader::VideoReader(VideoReader&&) noexcept = default;
VideoReader& VideoReader::operator=(VideoReader&&) noexcept = default;

bool VideoReader::read(cv::Mat& bgr) {
  Impl& d = *impl_;
  if (!d.pending.empty()) {
    bgr = d.pending;
    d.pending.release();
    d.index = d.next;
    d.time = d.pendingTime;
    ++d.next;
    return true;
  }
  double seconds = 0.0;
  const int index = d.next;
  if (!d.decode(bgr, seconds)) {
    bgr.release();
    return false;
  }
  d.index = index;
  d.time = seconds;
  return true;
}

bool VideoReader::seek(int frame) {
  Impl& d = *impl_;
  if (frame < 0 || (d.frameCount > 0 && frame >= d.frameCount)) return false;
  if (frame == d.next && (!d.pending.empty() || frame == d.index + 1)) return true;
  const int previousNext = d.next;
  const int previousIndex = d.index;
  const double previousTime = d.time;
  if (d.position(frame)) {
    d.index = frame - 1;
    d.time = frame > 0 ? (frame - 1) / d.fps : 0.0;
    return true;
  }
  d.position(previousNext);
  d.index = previousIndex;
  d.time = previousTime;
  return false;
}

int VideoReader::frameIndex() const {
  return impl_->index;
}
double VideoReader::timestamp() const {
  return impl_->time;
}
double VideoReader::fps() const {
  return impl_->fps;
}
int VideoReader::frameCount() const {
  return impl_->frameCount;
}
int VideoReader::width() const {
  return impl_->width;
}
int VideoReader::height() const {
  return impl_->height;
}
const fs::path& VideoReader::path() const {
  return impl_->path;
}

}  // namespace clm3d
