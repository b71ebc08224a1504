// Writing a video file frame by frame through OpenCV's FFmpeg backend, saved the way the rest of
// the project saves: frames go to a temporary file beside the target, which is renamed over it only
// by close(), so an interrupted or failed run never leaves a truncated video under the final name.
// The codec follows the extension: .avi and .mkv are FFV1 (lossless, for synthetic test sequences
// whose pixels must be exactly what was rendered), .mp4 is MPEG-4 part 2 (small, lossy, for
// overlays people watch). docs/video.md.
#pragma once

#include <filesystem>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <string>

namespace clm3d {

class VideoWriter {
 public:
  // Opens "<stem>.partial-XXXXXX<ext>" beside `path` for frames of width x height at `fps`.
  // Width and height must be even (OpenCV's FFmpeg writer would silently crop an odd size).
  // Throws InputError naming `path` for an extension other than .avi, .mkv and .mp4 (listing
  // them), an odd size or a size or rate out of range, a folder that does not exist, or a file
  // FFmpeg cannot open for writing.
  VideoWriter(const std::filesystem::path& path, int width, int height, double fps);
  // Without close(), removes the temporary file: the target is left as it was.
  ~VideoWriter();
  VideoWriter(VideoWriter&&) noexcept;
  VideoWriter& operator=(VideoWriter&&) noexcept;
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // Appends a frame: 8-bit BGR or BGRA (alpha is dropped) of exactly width x height. Throws
  // InputError naming the file for any other frame, Error after close().
  void write(const cv::Mat& frame);

  // Finishes the file and renames it to path(). Throws InputError naming the file if it cannot be
  // finished or renamed (the temporary is then removed). Calling it again does nothing.
  void close();

  const std::filesystem::path& path() const;
  // The file frames are written to until close().
  const std::filesystem::path& temporaryPath() const;
  int framesWritten() const;
  bool isOpen() const;

  // The codecs by extension, for messages and help texts: ".avi, .mkv (FFV1, lossless); .mp4
  // (MPEG-4 part 2, lossy)".
  static std::string supportedFormats();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clm3d
