// Writes a video's frames as numbered images, named like the per-frame .pts files of a ground
// truth (frame_000042.png beside frame_000042.pts), so tools that read images only (annotation
// tools, other landmarkers such as dlib's) can work on a video and their points pair with the
// tracks CSV's frames by file stem (clm3d eval-points --truth-dir / --pred-dir).
#pragma once

#include <filesystem>
#include <string>

#include "core/common/progress.hpp"

namespace clm3d {

struct FrameExportSettings {
  int every = 1;                   // every Nth frame from `first` (>= 1)
  int first = 0;                   // 0-based
  int last = -1;                   // inclusive; -1: to the end of the video
  std::string extension = ".png";  // .png (lossless) or .jpg
};

struct FrameExportSummary {
  int written = 0;
  int videoFrames = 0;  // frames decoded (up to `last`, or the whole video)
};

// The file name of a frame's image or points: frame_000042 + extension (".png", ".pts").
std::filesystem::path frameFileName(int frame, const std::string& extension);

// Decodes `video` and writes the selected frames into `folder` (created if needed), each saved
// atomically, overwriting files of the same name. Progress stage "exporting frames". InputError
// for an unreadable video, bad settings (every < 1, first < 0, last < first, an extension other
// than .png/.jpg) or a folder that cannot be written; Cancelled when cancelled (the frames
// written so far stay).
FrameExportSummary exportFrames(const std::filesystem::path& video,
                                const std::filesystem::path& folder,
                                const FrameExportSettings& settings,
                                const ProgressCallback& progress = {},
                                const CancelToken* cancel = nullptr);

}  // namespace clm3d
