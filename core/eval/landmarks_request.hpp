// What `clm3d landmarks convert` and `clm3d landmarks info` are asked for, the convert's options
// described once as a table, and their runs: a landmark file converted to another format (by
// extension) and scheme (iBUG 68 to thesis25, else by landmark id; --keep a subset), or described
// (format, points, scheme, missing points by name). Core/scheme reads and writes the files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/option_table.hpp"

namespace clm3d {

struct LandmarksConvertRequest {
  std::filesystem::path in, out;
  std::string from, keep, to;
};

// Every option of `clm3d landmarks convert`, in its help's order.
const std::vector<Option<LandmarksConvertRequest>>& landmarksConvertOptions();

// Writes the converted file; returns what the command prints (points, present, scheme).
std::string runLandmarksConvert(const LandmarksConvertRequest& request);

// What `clm3d landmarks info` prints about `file`, read in `scheme` (empty: by point count).
std::string describeLandmarkFile(const std::filesystem::path& file, const std::string& scheme);

}  // namespace clm3d
