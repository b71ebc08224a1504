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

// Any decoded frame as 8-bit, 3-channel BGR, into bgr (its buffer reused when it fits; frame and
// bgr must not share one).
void toBgr(const cv::Mat& frame, cv::Mat& bgr, const fs::path& path) {
  cv::Mat eight = frame;
  if (frame.depth() == CV_16U) {
    frame.convertTo(eight, CV_8U, 1.0 / 257.0);
  } else if (frame.depth() != CV_8U) {
    throwInputError(path, "has frames of an unsupported pixel type");
  }
  switch (eight.channels()) {
    case 3:
      eight.copyTo(bgr);
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
}

// A presentation time gap of a whole number of frame intervals (within a quarter) beyond one:
// that many frames less one were in the container but not decoded.
int framesSkippedBetween(double before, double now, double fps) {
  if (!std::isfinite(before)) return 0;
  const double steps = (now - before) * fps;
  const double whole = std::round(steps);
  if (whole < 2.0 || std::abs(steps - whole) > 0.25 || whole > 1e6) return 0;
  return static_cast<int>(whole) - 1;
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
  int skipped = 0;    // undecodable frames just before it
  double lastDecodedTime = -std::numeric_limits<double>::infinity();
  // The container's time of the last decoded frame when it was usable, else NaN: the reference
  // for a gap (frames FFmpeg could not decode).
  double lastStatedTime = std::numeric_limits<double>::quiet_NaN();
  int lastSkipped = 0;  // what the last decode() skipped
  cv::Mat raw;          // OpenCV's frame before conversion, kept so its buffer is reused

  void open() {
    capture.release();
    // Exceptions from OpenCV (a corrupt file can make a backend throw) become InputErrors.
    try {
      // Software decoding, asked for: left to choose, OpenCV's FFmpeg backend first tries the
      // hardware decoders (VA-API and others), which on a machine without one cost 40-110 ms of
      // every open for nothing (docs/video.md); and where one exists its frames could differ
      // from the software decoder's, so the same video would track differently from machine to
      // machine.
      capture.open(path.string(), cv::CAP_FFMPEG,
                   {cv::CAP_PROP_HW_ACCELERATION, cv::VIDEO_ACCELERATION_NONE});
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
    lastStatedTime = std::numeric_limits<double>::quiet_NaN();
  }

  // Decodes frame `next` (moved on past frames the container has but FFmpeg could not decode:
  // lastSkipped) into bgr; false at the end.
  bool decode(cv::Mat& bgr, double& seconds) {
    bool ok = false;
    try {
      ok = capture.read(raw);
    } catch (const cv::Exception& e) {
      throwInputError(path,
                      "frame " + std::to_string(next) + " cannot be decoded (" + e.what() + ")");
    }
    if (!ok || raw.empty()) return false;
    if (raw.type() == CV_8UC3) {
      // Already BGR: hand the buffer over and decode the next frame into bgr's old one (a ring of
      // buffers stays a ring, one buffer larger).
      cv::swap(raw, bgr);
    } else {
      toBgr(raw, bgr, path);
    }
    const double stated = capture.get(cv::CAP_PROP_POS_MSEC) / 1000.0;
    const bool sane = std::isfinite(stated) && stated >= 0.0 &&
                      (next == 0 ? stated < 1.0 / fps + 1e-6 : stated > lastDecodedTime);
    lastSkipped = sane ? framesSkippedBetween(lastStatedTime, stated, fps) : 0;
    // Never beyond the frames the container declares: a variable-rate video's longer intervals
    // are not lost frames.
    if (frameCount > 0 && next + lastSkipped >= frameCount) lastSkipped = 0;
    next += lastSkipped;
    lastStatedTime = sane ? stated : std::numeric_limits<double>::quiet_NaN();
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
      lastStatedTime = std::numeric_limits<double>::quiet_NaN();
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
  bgr = cv::Mat();  // a fresh buffer: never one the caller still holds
  if (readInto(bgr)) return true;
  bgr.release();
  return false;
}

bool VideoReader::readInto(cv::Mat& bgr) {
  Impl& d = *impl_;
  if (!d.pending.empty()) {
    bgr = d.pending;  // the caller's buffer from here on
    d.pending.release();
    d.index = d.next;
    d.time = d.pendingTime;
    d.skipped = 0;
    ++d.next;
    return true;
  }
  double seconds = 0.0;
  if (!d.decode(bgr, seconds)) return false;
  d.index = d.next - 1;
  d.time = seconds;
  d.skipped = d.lastSkipped;
  return true;
}

bool VideoReader::seek(int frame) {
  Impl& d = *impl_;
  if (frame < 0 || (d.frameCount > 0 && frame >= d.frameCount)) return false;
  if (frame == d.next && (!d.pending.empty() || frame == d.index + 1)) return true;
  const int previousNext = d.next;
  const int previousIndex = d.index;
  const double previousTime = d.time;
  d.skipped = 0;
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
int VideoReader::skippedBefore() const {
  return impl_->skipped;
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
