#include "core/eval/scored_truth.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "core/common/error.hpp"
#include "core/eval/face_box.hpp"
#include "core/scheme/ibug68_conversion.hpp"
#include "core/scheme/landmark_file.hpp"

namespace clm3d {
namespace {

constexpr int kAflwPoints = 21;

// 1-based AFLW point -> thesis25 id, as score_aflw21.py pairs them.
struct AflwPair {
  int aflw;
  const char* thesisId;
};

std::vector<std::pair<int, int>> resolveAflwPairs() {
  static const AflwPair pairs[] = {
      {1, "right_brow_outer"},    {3, "right_brow_inner"},   {4, "left_brow_inner"},
      {6, "left_brow_outer"},     {7, "right_eye_outer"},    {8, "right_eye_centre"},
      {9, "right_eye_inner"},     {10, "left_eye_inner"},    {11, "left_eye_centre"},
      {12, "left_eye_outer"},     {13, "right_earlobe"},     {14, "right_nose_base"},
      {15, "nose_tip"},           {16, "left_nose_base"},    {17, "left_earlobe"},
      {18, "right_mouth_corner"}, {20, "left_mouth_corner"}, {21, "chin_centre"},
  };
  std::vector<std::pair<int, int>> table;
  for (const AflwPair& pair : pairs) {
    const int thesis = Scheme::thesis25().indexOf(pair.thesisId);
    if (thesis < 0) throw std::logic_error(std::string("unknown thesis25 id ") + pair.thesisId);
    table.emplace_back(pair.aflw - 1, thesis);
  }
  return table;
}

}  // namespace

const std::vector<std::pair<int, int>>& aflw21ToThesis25Pairs() {
  static const std::vector<std::pair<int, int>> table = resolveAflwPairs();
  return table;
}

LandmarkSet aflw21ToThesis25(const LandmarkSet& aflw21) {
  if (aflw21.size() != kAflwPoints) {
    throw std::invalid_argument("the AFLW pairing needs 21 points, not " +
                                std::to_string(aflw21.size()));
  }
  LandmarkSet result(Scheme::thesis25().size(), aflw21.dims());
  for (const auto& [aflw, thesis] : aflw21ToThesis25Pairs()) {
    if (aflw21.has(aflw)) result.set(thesis, aflw21.point(aflw));
  }
  return result;
}

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
  } else if (thesis && marked.size() == kAflwPoints) {
    dropInvisibleMarks(marked, file);
    truth.points = aflw21ToThesis25(marked);
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
