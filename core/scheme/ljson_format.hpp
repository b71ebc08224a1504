// menpo's landmark JSON (LJSON), as read and written by menpo and landmarker.io. Versions 1, 2
// and 3 are read, version 3 is written. Conventions (those of menpo, so files interoperate):
// - 2D points are stored (y, x) = (row, column), 0-based; in memory they are (x, y). 3D points are
//   stored and held as (x, y, z).
// - null coordinates mark a missing point.
// - Version 3 holds named groups; the first group is read. Files whose labels follow a layout
//   the scheme declares (ljson_layouts, e.g. landmarker.io's iBUG 68 template) are reordered to
//   the scheme's order by applyLjsonLayout.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

struct LjsonLabel {
  std::string name;
  std::vector<int> indices;  // 0-based point indices, in file order
};

struct LjsonLandmarks {
  LandmarkSet points;  // in file order
  std::vector<LjsonLabel> labels;
  std::string group;  // the version 3 group read ("" for versions 1 and 2)
};

// Throws InputError naming sourceName and the field for malformed input.
LjsonLandmarks parseLjson(std::string_view text, const std::string& sourceName);

// The points in scheme order: reordered when the file's labels match one of the scheme's
// ljsonLayouts(), otherwise as in the file. Returns true in `reordered` when a layout matched.
LandmarkSet applyLjsonLayout(const LjsonLandmarks& file, const Scheme& scheme,
                             bool* reordered = nullptr);

// Version 3 text with one group named after the scheme, labelled by the scheme's regions (points
// in no region go to a label "other", since menpo wants every point labelled).
std::string formatLjson(const LandmarkSet& points, const Scheme& scheme);

}  // namespace clm3d
