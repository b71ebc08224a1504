// clm3d truth: a ground truth for a video from a tracker output, hand-placed keyframes and
// interpolation, as CSV, .pts per frame and COCO keypoints (docs/ground-truth.md). The options and
// the run are core's (core/track/truth_request).
#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/track/truth_request.hpp"

namespace clm3d::cli {

void addTruthCommand(CLI::App& root) {
  addRequestCommand(root, "truth",
                    "Build a ground truth from a tracker output and hand-placed keyframes, "
                    "interpolating between keyframes; writes the ground-truth CSV and optionally "
                    "one .pts per frame and COCO keypoints JSON",
                    truthOptions(),
                    [](const TruthRequest& request, const CLI::App&) { return runTruth(request); });
}

}  // namespace clm3d::cli
