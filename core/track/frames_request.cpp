#include "core/track/frames_request.hpp"

namespace clm3d {
namespace frames_request_detail {

using R = FramesRequest;

std::vector<Option<R>> makeOptions() {
  return {
      textOption<R>(requiredOption("video", "video to read"), &R::video),
      textOption<R>(requiredOption("out", "folder for the images (created if needed)"), &R::out),
      integerOption<R>(commandOption("every", "every Nth frame", 1, 1000000),
                       [](R& r) -> int& { return r.settings.every; }),
      integerOption<R>(commandOption("first", "first frame (0-based)", 0, 100000000),
                       [](R& r) -> int& { return r.settings.first; }),
      integerOption<R>(commandOption("last", "last frame, inclusive (-1 = the end)", -1, 100000000),
                       [](R& r) -> int& { return r.settings.last; }),
      textChoiceOption<R>(commandOption("format", "image format"), &R::format, {"png", "jpg"}),
      flagOption<R>(commandOption("quiet", "no progress on stderr"), &R::quiet),
  };
}

}  // namespace frames_request_detail

const std::vector<Option<FramesRequest>>& framesOptions() {
  static const std::vector<Option<FramesRequest>> table = frames_request_detail::makeOptions();
  return table;
}

std::string runFrames(const FramesRequest& request, const ProgressCallback& progress,
                      const CancelToken* cancel) {
  FrameExportSettings settings = request.settings;
  settings.extension = "." + request.format;
  const FrameExportSummary summary =
      exportFrames(request.video, request.out, settings, progress, cancel);
  return "wrote " + std::to_string(summary.written) + " of " + std::to_string(summary.videoFrames) +
         " frames of " + request.video.string() + " to " + request.out.string() + '\n';
}

}  // namespace clm3d
