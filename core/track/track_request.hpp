// What `clm3d track` is asked for besides the tracker table's Track options (core/track/
// tracker_options, --faces among them, which the CLI adds itself): the files, described once as an
// option table, and its run: the video tracked (one face, or every face with a face column),
// the rows streamed into the tracks CSV, the overlay video drawn, the summary to print. A run
// cancelled keeps the frames tracked so far; the output's failure then says so.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/common/command_report.hpp"
#include "core/common/option_table.hpp"
#include "core/common/progress.hpp"
#include "core/track/tracker_options.hpp"

namespace clm3d {

struct TrackRequest {
  std::filesystem::path model, video, out, overlay, init;
  int last = -1;  // the last frame tracked, inclusive (-1 = the end)
  bool quiet = false;
  // From the tracker table's Track options and --fov (verticalFovDeg), which the CLI adds beside
  // these.
  TrackerSettings tracker;
};

// The options of `clm3d track` that are not the tracker table's, in its help's order.
const std::vector<Option<TrackRequest>>& trackRequestOptions();

// Tracks the video. `progress` hears the tracking, `rowsWritten` the rows written so far after
// each frame (both from the calling thread).
CommandReport runTrack(const TrackRequest& request, const ProgressCallback& progress,
                       const std::function<void(std::size_t)>& rowsWritten,
                       const CancelToken* cancel);

}  // namespace clm3d
