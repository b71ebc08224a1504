// What `clm3d fit` is asked for besides the tracker table's Fit options (core/track/
// tracker_options, which the CLI adds itself): the files, described once as an option table, and
// its run: one image fitted and written (and drawn), or many with the model loaded once and their
// summary (core/track/batch_fit). What to print comes back as a CommandReport whose failure says
// why the command exits 1 (a rejected fit without --keep-rejected, images with errors).
#pragma once

#include <filesystem>
#include <vector>

#include "core/common/command_report.hpp"
#include "core/common/option_table.hpp"
#include "core/common/progress.hpp"
#include "core/track/tracker_options.hpp"

namespace clm3d {

struct FitRequest {
  std::filesystem::path model, image, images, init, out, overlay, outDir, initDir;
  bool quiet = false;
  bool keepRejected = false;
  double startOffset = 0.0;
  // From the tracker table's Fit options and --fov (verticalFovDeg), which the CLI adds beside
  // these.
  TrackerSettings tracker;
};

// The options of `clm3d fit` that are not the tracker table's, in its help's order.
const std::vector<Option<FitRequest>>& fitRequestOptions();

// One image (--image) or many (--images); `progress` hears each image of many.
CommandReport runFit(const FitRequest& request, const ProgressCallback& progress,
                     const CancelToken* cancel);

}  // namespace clm3d
