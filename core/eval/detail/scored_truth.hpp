// A hand mark-up read for scoring against predictions in the model's scheme, whatever scheme the
// mark-up is in: the one place in eval that pairs another scheme's points with the model's (iBUG
// 68 through core/scheme's table; AFLW's 21 points with thesis25 through
// core/scheme/scheme_map, as ../shared/tools/score_aflw21.py pairs them) and keeps the face box of
// the file's own points, so that the box error of `clm3d eval-points` is that of the truth as
// marked (the 68-point box, the box of AFLW's visible points), not of the subset the schemes share.
// docs/evaluation.md, "Truths in other schemes".
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

struct ScoredTruth {
  // In the scoring scheme's order and size; points the file does not mark (invisible, "-1 -1" in
  // a .pts) or that have no counterpart in the file's scheme are missing.
  LandmarkSet points;
  // sqrt(w * h) of the box of every point the file marks (all of them, not only the paired ones);
  // NaN for fewer than two points or a box without area.
  double boxSize = 0.0;
  // The file's scheme: the scoring scheme's name, "ibug68" or "aflw21".
  std::string fileScheme;
};

// Reads a truth file for scoring in `scheme`: a file of the scheme's size as it is; a 68-point
// file (iBUG) or a 21-point file (AFLW) converted when the scheme is thesis25. A .pts point written
// "-1 -1" is missing. InputError naming the file: unreadable, or a point count the scheme cannot
// be paired with.
ScoredTruth readScoredTruth(const std::filesystem::path& file, const Scheme& scheme);

// Marks missing every point of a .pts set written "-1 -1" (AFLW's invisible point, read 0-based as
// (-2, -2)); other formats are left as they are.
void dropInvisibleMarks(LandmarkSet& set, const std::filesystem::path& file);

}  // namespace clm3d
