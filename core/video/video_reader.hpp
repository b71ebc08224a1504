// Reading a video file frame by frame, with each frame's index and time, through OpenCV's FFmpeg
// backend: what the tracker, the evaluation and the studio's player read their input with. A file
// that is missing or is not a video is an InputError naming it, never a crash or an empty video.
#pragma once

#include <filesystem>
#include <memory>
#include <opencv2/core/mat.hpp>

namespace clm3d {

class VideoReader {
 public:
  // Opens the file and decodes its first frame (so a file FFmpeg opens but cannot decode fails
  // here). Throws InputError "FILE: no such file", "FILE: is a folder, not a video" or
  // "FILE: cannot be read as a video (...)".
  explicit VideoReader(const std::filesystem::path& path);
  ~VideoReader();
  VideoReader(VideoReader&&) noexcept;
  VideoReader& operator=(VideoReader&&) noexcept;
  VideoReader(const VideoReader&) = delete;
  VideoReader& operator=(const VideoReader&) = delete;

  // The next frame as 8-bit BGR (CV_8UC3, a fresh buffer each call); false at the end of the
  // video (bgr is then left empty).
  bool read(cv::Mat& bgr);
  // The same into bgr's own buffer when it already has the frame's size and type (no allocation
  // per frame: the decode thread's ring, core/video/frame_prefetcher). Anything sharing that buffer
  // sees it overwritten. False at the end (bgr then unchanged).
  bool readInto(cv::Mat& bgr);

  // Makes the next read() return frame `frame` (0-based). False, with the position unchanged, if
  // the frame is outside the video. Exact for every codec: when the container's seek does not
  // land on the frame, the video is decoded forward from its start.
  bool seek(int frame);

  // Index of the last frame read (0-based); -1 before the first read() and after seek(0). Counts
  // the frames the decoder could not read (skippedBefore()), so it stays the frame's place in the
  // video.
  int frameIndex() const;
  // How many frames just before the last one read could not be decoded: the container holds them
  // (the last frame's presentation time is that many whole frame intervals, plus one, after the
  // previous frame's, and the video declares at least that many frames), but FFmpeg gave no image.
  // 0 normally, and always after a seek or when the times are not usable. docs/video.md.
  int skippedBefore() const;
  // Time of the last frame read, in seconds from the start: the frame's presentation time when the
  // container gives a sane one (finite, non-negative, increasing), else frameIndex() / fps().
  double timestamp() const;
  // Frames per second stated by the file; 30 when it states none.
  double fps() const;
  // Number of frames as stated by the container (an estimate for some formats); -1 if unknown.
  // May be more than can be decoded (a truncated file): see unreadableFrames in core/track.
  int frameCount() const;
  int width() const;
  int height() const;
  const std::filesystem::path& path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clm3d
