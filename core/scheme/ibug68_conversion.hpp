// The one mapping from the 68 iBUG points to the thesis's 25, so that every tool (the converter,
// readers of 68-point files, an annotator placing james's 25 points in 3D) uses the same table.
// A thesis point is the mean of its iBUG sources (one source for most, the six eye-contour points
// for an eye centre, the two inner eye corners for the point between the eyes); it is missing when
// it has no sources (the earlobes) or when any source is missing. Reasoning in docs/landmarks.md.
#pragma once

#include <string_view>
#include <vector>

#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme_map.hpp"

namespace clm3d {

struct Thesis25FromIbug68 {
  int thesisIndex;               // 0-based thesis25 index
  std::vector<int> ibugIndices;  // 0-based iBUG indices averaged; empty = no counterpart
  std::string_view note;         // how exact the correspondence is
};

// 25 entries, in thesis25 order.
const std::vector<Thesis25FromIbug68>& thesis25FromIbug68Table();

// True for the thesis25 points (0-based) a 68-point mark-up gives only from its jaw contour: the
// cheeks and the chin sides (thesis 20, 21, 23, 24). The contour's points slide along the jaw from
// one face to the next, so these have no fixed anatomical place: training does not learn them from
// photos, and photo sequences leave them out of their truth.
bool isJawContourPoint(int thesisIndex);

// The table as a scheme map (core/scheme/scheme_map.hpp): point 1 is Derived (not trusted to train
// patches), the jaw-contour points are Contour, the others Exact.
const SchemeMap& ibug68ToThesis25Map();

// Converts a 68-point iBUG set (2D or 3D, iBUG .pts order) to thesis25 order and size (the map's
// apply). Throws std::invalid_argument if ibug68 does not have 68 points.
LandmarkSet ibug68ToThesis25(const LandmarkSet& ibug68);

}  // namespace clm3d
