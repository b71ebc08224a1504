#include "core/track/frame_export.hpp"

#include <cstdio>
#include <opencv2/core/mat.hpp>

#include "core/common/error.hpp"
#include "core/video/video_reader.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {

std::filesystem::path frameFileName(int frame, const std::string& extension) {
  char name[32];
  std::snprintf(name, sizeof(name), "frame_%06d", frame);
  return std::string(name) + extension;
}

FrameExportSummary exportFrames(const std::filesystem::path& video,
                                const std::filesystem::path& folder,
                                const FrameExportSettings& settings,
                                const ProgressCallback& progress, const CancelToken* cancel) {
  if (settings.every < 1) throw InputError("frame export: every must be at least 1");
  if (settings.first < 0) throw InputError("frame export: the first frame must be 0 or more");
  if (settings.last >= 0 && settings.last < settings.first) {
    throw InputError("frame export: the last frame comes before the first");
  }
  if (settings.extension != ".png" && settings.extension != ".jpg") {
    throw InputError("frame export: format \"" + settings.extension + "\" is not .png or .jpg");
  }
  VideoReader reader(video);
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error)
    throw InputError(folder.string() + ": cannot create the folder (" + error.message() + ")");

  const int count = reader.frameCount();
  const int end =
      settings.last >= 0 && (count < 0 || settings.last < count) ? settings.last + 1 : count;
  if (settings.first > 0 && !reader.seek(settings.first)) {
    throw InputError(video.string() + ": frame " + std::to_string(settings.first) +
                     " is beyond the video's end");
  }
  FrameExportSummary summary;
  cv::Mat frame;
  while (settings.last < 0 || reader.frameIndex() < settings.last) {
    if (cancel != nullptr) cancel->throwIfCancelled();
    if (!reader.read(frame)) break;
    const int index = reader.frameIndex();
    ++summary.videoFrames;
    if ((index - settings.first) % settings.every == 0) {
      writeImage(folder / frameFileName(index, settings.extension), frame);
      ++summary.written;
    }
    if (progress && end > settings.first) {
      progress(static_cast<double>(index - settings.first + 1) / (end - settings.first),
               "exporting frames");
    }
  }
  if (progress) progress(1.0, "exporting frames");
  return summary;
}

}  // namespace clm3d
