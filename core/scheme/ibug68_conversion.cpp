#include "core/scheme/ibug68_conversion.hpp"

#include <stdexcept>
#include <string>

#include "core/scheme/scheme.hpp"

namespace clm3d {
namespace {

struct Row {
  const char* thesisId;
  std::vector<const char*> ibugIds;
  const char* note;
};

// By id, so the table reads against resources/schemes/*.json.
const std::vector<Row>& rows() {
  static const std::vector<Row> table = {
      {"mid_eyes",
       {"right_eye_3", "left_eye_0"},
       "derived: midpoint of the inner eye corners (iBUG 39, 42); iBUG 27 sits higher on the "
       "bridge"},
      {"left_eye_outer", {"left_eye_3"}, "exact (iBUG 45)"},
      {"right_eye_outer", {"right_eye_0"}, "exact (iBUG 36)"},
      {"left_brow_outer", {"left_brow_4"}, "exact (iBUG 26)"},
      {"left_brow_inner", {"left_brow_0"}, "exact (iBUG 22)"},
      {"right_brow_inner", {"right_brow_4"}, "exact (iBUG 21)"},
      {"right_brow_outer", {"right_brow_0"}, "exact (iBUG 17)"},
      {"left_eye_centre",
       {"left_eye_0", "left_eye_1", "left_eye_2", "left_eye_3", "left_eye_4", "left_eye_5"},
       "derived: mean of the left eye contour (iBUG 42-47)"},
      {"left_eye_inner", {"left_eye_0"}, "exact (iBUG 42)"},
      {"right_eye_inner", {"right_eye_3"}, "exact (iBUG 39)"},
      {"right_eye_centre",
       {"right_eye_0", "right_eye_1", "right_eye_2", "right_eye_3", "right_eye_4", "right_eye_5"},
       "derived: mean of the right eye contour (iBUG 36-41)"},
      {"nose_tip", {"nose_bridge_3"}, "exact (iBUG 30)"},
      {"left_nose_base", {"nose_base_4"}, "close: iBUG 35 is the left end of the nostril base"},
      {"right_nose_base", {"nose_base_0"}, "close: iBUG 31 is the right end of the nostril base"},
      {"left_mouth_corner", {"outer_lip_06"}, "exact (iBUG 54)"},
      {"right_mouth_corner", {"outer_lip_00"}, "exact (iBUG 48)"},
      {"upper_lip_top", {"outer_lip_03"}, "exact (iBUG 51)"},
      {"lower_lip_bottom", {"outer_lip_09"}, "exact (iBUG 57)"},
      {"left_earlobe", {}, "none: the iBUG jaw contour stops in front of the ear"},
      {"left_cheek",
       {"jaw_13"},
       "approximate: the left jaw contour at about mouth height (iBUG 13)"},
      {"left_chin", {"jaw_10"}, "approximate: left of the chin on the jaw contour (iBUG 10)"},
      {"chin_centre", {"jaw_08"}, "exact (iBUG 8)"},
      {"right_chin", {"jaw_06"}, "approximate: right of the chin on the jaw contour (iBUG 6)"},
      {"right_cheek",
       {"jaw_03"},
       "approximate: the right jaw contour at about mouth height (iBUG 3)"},
      {"right_earlobe", {}, "none: the iBUG jaw contour stops in front of the ear"},
  };
  return table;
}

std::vector<Thesis25FromIbug68> resolve() {
  const auto& thesis = Scheme::thesis25();
  const auto& ibug = Scheme::ibug68();
  std::vector<Thesis25FromIbug68> table;
  for (const auto& row : rows()) {
    Thesis25FromIbug68 entry{thesis.indexOf(row.thesisId), {}, row.note};
    if (entry.thesisIndex != static_cast<int>(table.size())) {
      throw std::logic_error(std::string("ibug68 conversion table out of order at ") +
                             row.thesisId);
    }
    for (const char* id : row.ibugIds) {
      const int index = ibug.indexOf(id);
      if (index < 0) throw std::logic_error(std::string("unknown iBUG id in table: ") + id);
      entry.ibugIndices.push_back(index);
    }
    table.push_back(std::move(entry));
  }
  if (static_cast<int>(table.size()) != thesis.size()) {
    throw std::logic_error("ibug68 conversion table does not cover thesis25");
  }
  return table;
}

}  // namespace

const std::vector<Thesis25FromIbug68>& thesis25FromIbug68Table() {
  static const std::vector<Thesis25FromIbug68> table = resolve();
  return table;
}

const SchemeMap& ibug68ToThesis25Map() {
  static const SchemeMap map = [] {
    SchemeMap m;
    m.source = "ibug68";
    m.sourcePoints = 68;
    m.target = Scheme::thesis25().name();
    for (const auto& entry : thesis25FromIbug68Table()) {
      // Point 1, the centre between the eyes, is the midpoint of the inner eye corners here: a
      // construction, where the 3D annotations put the point on the bridge of the nose, above and
      // in front of that line.
      const MapTrust trust = entry.thesisIndex == 0                 ? MapTrust::Derived
                             : isJawContourPoint(entry.thesisIndex) ? MapTrust::Contour
                                                                    : MapTrust::Exact;
      m.entries.push_back({entry.ibugIndices, trust});
    }
    return m;
  }();
  return map;
}

LandmarkSet ibug68ToThesis25(const LandmarkSet& ibug68) {
  return ibug68ToThesis25Map().apply(ibug68);
}

bool isJawContourPoint(int thesisIndex) {
  return thesisIndex == 19 || thesisIndex == 20 || thesisIndex == 22 || thesisIndex == 23;
}

}  // namespace clm3d
