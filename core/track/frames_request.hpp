// What `clm3d frames` is asked for, described once as an option table over the frame export's
// settings (core/track/frame_export), and its run: a video's frames as numbered images.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/option_table.hpp"
#include "core/common/progress.hpp"
#include "core/track/frame_export.hpp"

namespace clm3d {

struct FramesRequest {
  std::filesystem::path video, out;
  FrameExportSettings settings;
  std::string format = "png";
  bool quiet = false;
};

// Every option of `clm3d frames`, in its help's order.
const std::vector<Option<FramesRequest>>& framesOptions();

// Writes the frames; returns what the command prints (frames written of the video's).
std::string runFrames(const FramesRequest& request, const ProgressCallback& progress,
                      const CancelToken* cancel);

}  // namespace clm3d
