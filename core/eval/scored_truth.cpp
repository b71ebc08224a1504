#include "core/eval/detail/scored_truth.hpp"

#include <limits>
#include <string>

#include "core/common/error.hpp"
#include "core/geometry/face_box.hpp"
#include "core/scheme/ibug68_conversion.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme_map.hpp"

namespace clm3d {
namespace {

// The points of `marked` that `map` pairs exactly with the scoring scheme (score_aflw21.py's
// pairs: a derived point such as AFLW's midpoint of the inner eye corners is not scored).
LandmarkSet exactlyPaired(const SchemeMap& map, const LandmarkSet& marked) {
  LandmarkSet points = map.apply(marked);
  for (int i = 0; i < points.size(); ++i) {
    if (map.entries[static_cast<std::size_t>(i)].trust != MapTrust::Exact) points.setMissing(i);
  }
  return points;
}

}  // namespace

void dropInvisibleMarks(LandmarkSet& set, const std::filesystem::path& file) {
  if (file.extension() != ".pts") return;
  for (int i = 0; i < set.size(); ++i) {
    if (set.has(i) && set.point(i).x() == -2.0 && set.point(i).y() == -2.0) set.setMissing(i);
  }
}

ScoredTruth readScoredTruth(const std::filesystem::path& file, const Scheme& scheme) {
  LandmarkSet marked = readLandmarks(file);
  ScoredTruth truth;
  const bool thesis = scheme.name() == Scheme::thesis25().name();
  if (marked.size() == scheme.size()) {
    marked = readLandmarks(file, &scheme);  // the scheme's order (LJSON layouts, CSV ids)
    dropInvisibleMarks(marked, file);
    truth.points = marked;
    truth.fileScheme = scheme.name();
  } else if (thesis && marked.size() == 68) {
    dropInvisibleMarks(marked, file);
    truth.points = ibug68ToThesis25(marked);
    truth.fileScheme = "ibug68";
  } else if (thesis && marked.size() == aflw21ToThesis25Map().sourcePoints) {
    dropInvisibleMarks(marked, file);
    truth.points = exactlyPaired(aflw21ToThesis25Map(), marked);
    truth.fileScheme = "aflw21";
  } else {
    throwInputError(
        file, "has " + std::to_string(marked.size()) + " points, scheme " + scheme.name() +
                  " expects " + std::to_string(scheme.size()) +
                  (thesis ? " (68-point iBUG and 21-point AFLW files are paired with it)" : ""));
  }
  const Eigen::Matrix3Xd all = marked.matrix();
  const double box = faceBoxSize(all.topRows<2>());
  truth.boxSize = box > 0.0 ? box : std::numeric_limits<double>::quiet_NaN();
  return truth;
}

}  // namespace clm3d
