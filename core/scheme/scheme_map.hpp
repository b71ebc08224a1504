// A landmark map from another mark-up scheme to the model's: which points of a photo's landmark
// file give each of the model's points, and which of them are trusted to train patch experts. One
// mechanism for every foreign scheme a training photo may come in (the iBUG 68 points of LFPW, the
// AFLW 21 points with their invisible points), so that loading, conversion and trust are decided
// in one place. Maps are static tables: callers keep nothing alive.
#pragma once

#include <string>
#include <vector>

#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

// How far a mapped point can be trusted to teach a patch expert where the point is.
enum class MapTrust {
  Exact,    // the source marks the same anatomical place
  Derived,  // a construction (e.g. a midpoint) the model's mark-up does not agree with: no patches
  Contour,  // a point of a sliding contour (iBUG's jaw): patches only when the source says so
};

struct SchemeMapEntry {
  std::vector<int> sources;  // 0-based source indices averaged; empty = no counterpart
  MapTrust trust = MapTrust::Exact;
};

struct SchemeMap {
  std::string source;  // the source scheme's name ("ibug68", "aflw21")
  int sourcePoints = 0;
  std::string target;                   // the model scheme's name ("thesis25")
  std::vector<SchemeMapEntry> entries;  // one per target landmark, in target order
  // A source point with both coordinates below 0 is invisible, not a point: AFLW writes the points
  // hidden by the head's own turn as "-1 -1", off the image above and left of its first pixel
  // (the 1-based .pts reads it as (-2, -2)).
  bool offImageIsInvisible = false;

  // The source set in target order: a target point is the mean of its sources, missing when it
  // has none or any source is missing (or invisible). Throws std::invalid_argument when `points`
  // does not have sourcePoints points.
  LandmarkSet apply(const LandmarkSet& points) const;
  // Per target landmark: present in `mapped` (apply's result) and trusted to train patches (Exact;
  // Contour only with `trustContour`).
  std::vector<bool> trusted(const LandmarkSet& mapped, bool trustContour) const;
};

// The iBUG 68 -> thesis25 map (core/scheme/ibug68_conversion.hpp's table).
const SchemeMap& ibug68ToThesis25Map();
// The AFLW 21 -> thesis25 map: 18 of the 21 points have an exact thesis counterpart (brow corners,
// eye corners and centres, ear lobes, nose sides and tip, mouth corners, chin centre); the brow
// centres and the mouth centre have none. AFLW's "left" is the image's left (the subject's right).
const SchemeMap& aflw21ToThesis25Map();

// The built-in map whose source has `points` points and whose target is `target`, or nullptr.
const SchemeMap* schemeMapFor(int points, const Scheme& target);

}  // namespace clm3d
