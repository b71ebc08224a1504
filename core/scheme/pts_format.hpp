// The iBUG / ASM .pts landmark format ("version: 1", "n_points: N", "{", one "x y" or "x y z"
// line per point, "}"). Pixel coordinates are 1-based on disk (MATLAB convention, as in the iBUG
// and 300-W data) and 0-based in memory: x and y shift by one, z never does. A missing point is
// written and read as "nan nan" (or "nan nan nan").
#pragma once

#include <string>
#include <string_view>

#include "core/scheme/landmark_set.hpp"

namespace clm3d {

// Parses .pts text; sourceName names the file in errors ("FILE:LINE: what").
// Throws InputError for any malformed input.
LandmarkSet parsePts(std::string_view text, const std::string& sourceName);
std::string formatPts(const LandmarkSet& points);

}  // namespace clm3d
