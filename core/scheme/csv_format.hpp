// One landmark set as CSV, for spreadsheets and scripts: a header "id,x,y" (2D) or "id,x,y,z"
// (3D), then one row per landmark "id,x,y[,z]" in scheme order. Coordinates are as in memory
// (0-based pixels for 2D, model millimetres for 3D). Empty coordinate cells (or "nan") mark a
// missing point. No quoting: ids are plain words.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

struct CsvLandmarks {
  LandmarkSet points;            // in file order
  std::vector<std::string> ids;  // id of each row
  std::vector<int> lines;        // 1-based line of each row, for messages
};

// Throws InputError naming sourceName and the line for malformed input.
CsvLandmarks parseLandmarkCsv(std::string_view text, const std::string& sourceName);

// The points in scheme order, placed by id; rows the scheme lacks are an InputError naming the
// line, scheme points without a row are missing.
LandmarkSet csvToScheme(const CsvLandmarks& file, const Scheme& scheme,
                        const std::string& sourceName);

std::string formatLandmarkCsv(const LandmarkSet& points, const Scheme& scheme);

}  // namespace clm3d
