// What `clm3d adapt` is asked for, described once as an option table (the files and the
// adaptation's settings, core/train/model_adaptation.hpp), and its run: the general model adapted
// to the corrected frames of one video's ground truth (core/track/video_adaptation.hpp) and saved
// atomically as an ordinary model file, so that a cancelled or failed run leaves no output.
#pragma once

#include <filesystem>
#include <vector>

#include "core/common/command_report.hpp"
#include "core/common/option_table.hpp"
#include "core/common/progress.hpp"
#include "core/train/model_adaptation.hpp"

namespace clm3d {

struct AdaptRequest {
  std::filesystem::path model, video, truth, out;
  AdaptSettings settings;
  bool quiet = false;
};

// Every option of `clm3d adapt`, in its help's order.
const std::vector<Option<AdaptRequest>>& adaptRequestOptions();

// Adapts and saves; returns what the command prints (frames used and skipped, experts and
// template means moved, the time, the file written).
CommandReport runAdapt(const AdaptRequest& request, const ProgressCallback& progress = {},
                       const CancelToken* cancel = nullptr);

}  // namespace clm3d
