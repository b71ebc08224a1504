// What `clm3d truth` is asked for, described once as an option table (the CLI builds the
// command's options from it), and its run: a ground truth built from a tracker output (or an
// earlier ground truth, COCO keypoints, or nothing), hand-placed keyframes from landmark files and
// interpolation (core/track/ground_truth), written as CSV, one .pts per frame and COCO keypoints
// (core/track/coco_keypoints) as asked (docs/ground-truth.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/option_table.hpp"

namespace clm3d {

struct TruthRequest {
  std::filesystem::path in;
  int frames = -1;                     // none given
  std::vector<std::string> keyframes;  // FRAME=FILE
  std::vector<std::string> clear;      // FRAME
  bool interpolate = false;
  std::filesystem::path out, pts, coco, video;
  std::string imageSize;  // WxH
  std::string scheme;
};

// Every option of `clm3d truth`, in its help's order.
const std::vector<Option<TruthRequest>>& truthOptions();

// Writes the ground truth (and the .pts and COCO files asked for); returns what the command
// prints: the files written with their frames, keyframes and landmarks.
std::string runTruth(const TruthRequest& request);

}  // namespace clm3d
