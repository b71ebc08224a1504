#include "core/video/video_writer.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <opencv2/core/check.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <random>
#include <system_error>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxSide = 16384;

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// FOURCC of the codec for the extension; 0 if the extension is not supported.
int codecFor(const std::string& ext) {
  if (ext == ".avi" || ext == ".mkv") return cv::VideoWriter::fourcc('F', 'F', 'V', '1');
  if (ext == ".mp4") return cv::VideoWriter::fourcc('m', 'p', '4', 'v');
  return 0;
}

fs::path temporaryBeside(const fs::path& path) {
  std::random_device device;
  char tag[16];
  std::snprintf(tag, sizeof tag, "%06x", static_cast<unsigned>(device() & 0xffffffu));
  return path.parent_path() /
         (path.stem().string() + ".partial-" + tag + path.extension().string());
}

}  // namespace

struct VideoWriter::Impl {
  fs::path path;
  fs::path temporary;
  cv::VideoWriter writer;
  int width = 0;
  int height = 0;
  int frames = 0;
  bool open = false;

  // Releases the encoder and removes the temporary file; never throws.
  void discard() noexcept {
    try {
      writer.release();
    } catch (...) {
    }
    open = false;
    std::error_code ec;
    fs::remove(temporary, ec);
  }
};

std::string VideoWriter::supportedFormats() {
  return ".avi, .mkv (FFV1, lossless); .mp4 (MPEG-4 part 2, lossy)";
}

VideoWriter::VideoWriter(const fs::path& path, int width, int height, double fps)
    : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  d.path = path;
  d.width = width;
  d.height = height;
  const std::string ext = lowerExtension(path);
  const int codec = codecFor(ext);
  if (codec == 0) {
    throwInputError(path,
                    "unsupported video format '" + ext + "'; supported: " + supportedFormats());
  }
  if (width < 2 || height < 2 || width > kMaxSide || height > kMaxSide) {
    throwInputError(path, "cannot write a video of " + std::to_string(width) + "x" +
                              std::to_string(height) + " pixels (each side 2.." +
                              std::to_string(kMaxSide) + ")");
  }
  // OpenCV's FFmpeg writer silently drops the last column or row of an odd size.
  if (width % 2 != 0 || height % 2 != 0) {
    throwInputError(path, "a video needs an even width and height, got " + std::to_string(width) +
                              "x" + std::to_string(height));
  }
  if (!std::isfinite(fps) || fps <= 0.0 || fps > 1000.0) {
    throwInputError(
        path, "frame rate must be in (0, 1000] frames per second, got " + std::to_string(fps));
  }
  const fs::path parent = path.parent_path();
  std::error_code ec;
  if (!parent.empty() && !fs::is_directory(parent, ec)) {
    throwInputError(path, "cannot write: folder " + parent.string() + " does not exist");
  }
  d.temporary = temporaryBeside(path);
  try {
    d.writer.open(d.temporary.string(), cv::CAP_FFMPEG, codec, fps, cv::Size(width, height), true);
  } catch (const cv::Exception& e) {
    d.discard();
    throwInputError(path, std::string("cannot be written as a video (") + e.what() + ")");
  }
  if (!d.writer.isOpened()) {
    d.discard();
    throwInputError(path, "cannot be written as a video (FFmpeg cannot open " +
                              d.temporary.filename().string() +
                              " for writing: folder not writable, or codec unavailable)");
  }
  d.open = true;
}

VideoWriter::~VideoWriter() {
  if (impl_ && impl_->open) impl_->discard();
}

VideoWriter::VideoWriter(VideoWriter&&) noexcept = default;

VideoWriter& VideoWriter::operator=(VideoWriter&& other) noexcept {
  if (this != &other) {
    if (impl_ && impl_->open) impl_->discard();
    impl_ = std::move(other.impl_);
  }
  return *this;
}

void VideoWriter::write(const cv::Mat& frame) {
  Impl& d = *impl_;
  if (!d.open) throw Error(fileMessage(d.path, "cannot write a frame: the video is closed"));
  const int channels = frame.channels();
  if (frame.empty() || frame.depth() != CV_8U || (channels != 3 && channels != 4) ||
      frame.cols != d.width || frame.rows != d.height) {
    throwInputError(d.path, "frame " + std::to_string(d.frames) + " is " +
                                std::to_string(frame.cols) + "x" + std::to_string(frame.rows) +
                                " " + cv::typeToString(frame.type()) +
                                "; expected 8-bit BGR or BGRA (CV_8UC3 or CV_8UC4) of " +
                                std::to_string(d.width) + "x" + std::to_string(d.height));
  }
  cv::Mat bgr = frame;
  if (channels == 4) cv::cvtColor(frame, bgr, cv::COLOR_BGRA2BGR);
  try {
    d.writer.write(bgr);
  } catch (const cv::Exception& e) {
    throwInputError(d.path,
                    "frame " + std::to_string(d.frames) + " cannot be encoded (" + e.what() + ")");
  }
  ++d.frames;
}

void VideoWriter::close() {
  Impl& d = *impl_;
  if (!d.open) return;
  try {
    d.writer.release();
  } catch (const cv::Exception& e) {
    d.discard();
    throwInputError(d.path, std::string("cannot finish the video (") + e.what() + ")");
  }
  d.open = false;
  std::error_code ec;
  if (!fs::is_regular_file(d.temporary, ec) || fs::file_size(d.temporary, ec) == 0) {
    d.discard();
    throwInputError(d.path, "cannot finish the video: FFmpeg wrote nothing (disk full?)");
  }
  fs::rename(d.temporary, d.path, ec);
  if (ec) {
    d.discard();
    throwInputError(d.path, "cannot replace file: " + ec.message());
  }
}

const fs::path& VideoWriter::path() const {
  return impl_->path;
}
const fs::path& VideoWriter::temporaryPath() const {
  return impl_->temporary;
}
int VideoWriter::framesWritten() const {
  return impl_->frames;
}
bool VideoWriter::isOpen() const {
  return impl_->open;
}

}  // namespace clm3d
