#include "core/scheme/scheme_map.hpp"

#include <stdexcept>
#include <string>

#include "core/scheme/ibug68_conversion.hpp"

namespace clm3d {
namespace {

struct AflwRow {
  const char* thesisId;
  std::vector<int> aflw;  // 1-based AFLW numbers (README order), averaged
  MapTrust trust;
};

// By thesis id, in thesis order; AFLW numbers as the data's README lists them ("left" = the
// image's left, so AFLW's left eye is the subject's right eye). The pairing is the one
// ../shared/tools/score_aflw21.py scores with.
const std::vector<AflwRow>& aflwRows() {
  static const std::vector<AflwRow> rows = {
      {"mid_eyes", {9, 10}, MapTrust::Derived},  // midpoint of the inner eye corners
      {"left_eye_outer", {12}, MapTrust::Exact},
      {"right_eye_outer", {7}, MapTrust::Exact},
      {"left_brow_outer", {6}, MapTrust::Exact},
      {"left_brow_inner", {4}, MapTrust::Exact},
      {"right_brow_inner", {3}, MapTrust::Exact},
      {"right_brow_outer", {1}, MapTrust::Exact},
      {"left_eye_centre", {11}, MapTrust::Exact},
      {"left_eye_inner", {10}, MapTrust::Exact},
      {"right_eye_inner", {9}, MapTrust::Exact},
      {"right_eye_centre", {8}, MapTrust::Exact},
      {"nose_tip", {15}, MapTrust::Exact},
      {"left_nose_base", {16}, MapTrust::Exact},
      {"right_nose_base", {14}, MapTrust::Exact},
      {"left_mouth_corner", {20}, MapTrust::Exact},
      {"right_mouth_corner", {18}, MapTrust::Exact},
      {"upper_lip_top", {}, MapTrust::Exact},     // AFLW marks the mouth centre only
      {"lower_lip_bottom", {}, MapTrust::Exact},  // likewise
      {"left_earlobe", {17}, MapTrust::Exact},
      {"left_cheek", {}, MapTrust::Exact},
      {"left_chin", {}, MapTrust::Exact},
      {"chin_centre", {21}, MapTrust::Exact},
      {"right_chin", {}, MapTrust::Exact},
      {"right_cheek", {}, MapTrust::Exact},
      {"right_earlobe", {13}, MapTrust::Exact},
  };
  return rows;
}

SchemeMap buildAflwMap() {
  const Scheme& thesis = Scheme::thesis25();
  SchemeMap map;
  map.source = "aflw21";
  map.sourcePoints = 21;
  map.target = thesis.name();
  map.offImageIsInvisible = true;
  for (const AflwRow& row : aflwRows()) {
    if (thesis.indexOf(row.thesisId) != static_cast<int>(map.entries.size())) {
      throw std::logic_error(std::string("aflw21 map out of order at ") + row.thesisId);
    }
    SchemeMapEntry entry;
    entry.trust = row.trust;
    for (const int number : row.aflw) entry.sources.push_back(number - 1);
    map.entries.push_back(std::move(entry));
  }
  if (static_cast<int>(map.entries.size()) != thesis.size()) {
    throw std::logic_error("aflw21 map does not cover thesis25");
  }
  return map;
}

}  // namespace

LandmarkSet SchemeMap::apply(const LandmarkSet& points) const {
  if (points.size() != sourcePoints) {
    throw std::invalid_argument(source + " conversion needs " + std::to_string(sourcePoints) +
                                " points, not " + std::to_string(points.size()));
  }
  const auto visible = [&](int i) {
    if (!points.has(i)) return false;
    const Eigen::Vector3d p = points.point(i);
    return !(offImageIsInvisible && p.x() < 0.0 && p.y() < 0.0);
  };
  LandmarkSet result(static_cast<int>(entries.size()), points.dims());
  for (std::size_t t = 0; t < entries.size(); ++t) {
    const SchemeMapEntry& entry = entries[t];
    if (entry.sources.empty()) continue;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    bool complete = true;
    for (const int s : entry.sources) {
      if (!visible(s)) {
        complete = false;
        break;
      }
      sum += points.point(s);
    }
    if (complete) {
      result.set(static_cast<int>(t),
                 Eigen::Vector3d(sum / static_cast<double>(entry.sources.size())));
    }
  }
  return result;
}

std::vector<bool> SchemeMap::trusted(const LandmarkSet& mapped, bool trustContour) const {
  std::vector<bool> result(entries.size(), false);
  for (std::size_t t = 0; t < entries.size(); ++t) {
    const MapTrust trust = entries[t].trust;
    result[t] = static_cast<int>(t) < mapped.size() && mapped.has(static_cast<int>(t)) &&
                (trust == MapTrust::Exact || (trust == MapTrust::Contour && trustContour));
  }
  return result;
}

const SchemeMap& aflw21ToThesis25Map() {
  static const SchemeMap map = buildAflwMap();
  return map;
}

const SchemeMap* schemeMapFor(int points, const Scheme& target) {
  for (const SchemeMap* map : {&ibug68ToThesis25Map(), &aflw21ToThesis25Map()}) {
    if (map->sourcePoints == points && map->target == target.name() &&
        static_cast<int>(map->entries.size()) == target.size()) {
      return map;
    }
  }
  return nullptr;
}

}  // namespace clm3d
