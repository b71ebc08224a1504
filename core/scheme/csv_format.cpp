#include "core/scheme/csv_format.hpp"

#include <cmath>
#include <unordered_set>

#include "core/common/error.hpp"
#include "core/scheme/text_scan.hpp"

namespace clm3d {

CsvLandmarks parseLandmarkCsv(std::string_view text, const std::string& sourceName) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte-order mark
  const auto lines = text::splitLines(text);
  std::size_t next = 0;
  while (next < lines.size() && text::trim(lines[next].text).empty()) ++next;
  if (next >= lines.size()) throwInputError(sourceName, "empty file: expected a header \"id,x,y\"");

  const auto header = text::splitCommas(lines[next].text);
  int dims = 0;
  if (header.size() == 3 && header[0] == "id" && header[1] == "x" && header[2] == "y") {
    dims = 2;
  } else if (header.size() == 4 && header[0] == "id" && header[1] == "x" && header[2] == "y" &&
             header[3] == "z") {
    dims = 3;
  } else {
    throwInputError(sourceName, "header must be \"id,x,y\" or \"id,x,y,z\"", lines[next].number);
  }
  ++next;

  std::vector<std::vector<double>> rows;
  CsvLandmarks result;
  std::unordered_set<std::string> seen;
  for (; next < lines.size(); ++next) {
    const auto& line = lines[next];
    if (text::trim(line.text).empty()) continue;
    const auto cells = text::splitCommas(line.text);
    if (static_cast<int>(cells.size()) != dims + 1) {
      throwInputError(
          sourceName,
          "expected " + std::to_string(dims + 1) + " cells, found " + std::to_string(cells.size()),
          line.number);
    }
    if (rows.size() >= static_cast<std::size_t>(text::kMaxLandmarkCount)) {
      throwInputError(sourceName,
                      "too many rows (at most " + std::to_string(text::kMaxLandmarkCount) + ")",
                      line.number);
    }
    const std::string id(cells[0]);
    if (id.empty()) throwInputError(sourceName, "empty landmark id", line.number);
    if (!seen.insert(id).second) {
      throwInputError(sourceName, "duplicate landmark id \"" + id + "\"", line.number);
    }
    std::vector<double> row;
    int missing = 0;
    for (int d = 0; d < dims; ++d) {
      const auto cell = cells[static_cast<std::size_t>(d + 1)];
      if (cell.empty()) {
        ++missing;
        row.push_back(0.0);
        continue;
      }
      const auto value = text::parseNumberOrNan(cell);
      if (!value) {
        throwInputError(sourceName, "\"" + std::string(cell) + "\" is not a finite number",
                        line.number);
      }
      missing += std::isnan(*value) ? 1 : 0;
      row.push_back(*value);
    }
    if (missing != 0 && missing != dims) {
      throwInputError(sourceName, "a missing point must leave every coordinate empty", line.number);
    }
    if (missing != 0) row.clear();
    rows.push_back(std::move(row));
    result.ids.push_back(id);
    result.lines.push_back(line.number);
  }

  result.points = LandmarkSet(static_cast<int>(rows.size()), dims);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    if (row.empty()) continue;
    result.points.set(static_cast<int>(i),
                      Eigen::Vector3d(row[0], row[1], dims == 3 ? row[2] : 0.0));
  }
  return result;
}

LandmarkSet csvToScheme(const CsvLandmarks& file, const Scheme& scheme,
                        const std::string& sourceName) {
  LandmarkSet result(scheme.size(), file.points.dims());
  for (int row = 0; row < file.points.size(); ++row) {
    const auto& id = file.ids[static_cast<std::size_t>(row)];
    const int index = scheme.indexOf(id);
    if (index < 0) {
      throwInputError(sourceName, "landmark id \"" + id + "\" is not in scheme " + scheme.name(),
                      file.lines[static_cast<std::size_t>(row)]);
    }
    if (file.points.has(row)) result.set(index, file.points.point(row));
  }
  return result;
}

std::string formatLandmarkCsv(const LandmarkSet& points, const Scheme& scheme) {
  std::string out = points.dims() == 3 ? "id,x,y,z\n" : "id,x,y\n";
  for (int i = 0; i < points.size(); ++i) {
    out += i < scheme.size() ? scheme.id(i) : "point_" + std::to_string(i);
    if (!points.has(i)) {
      out += points.dims() == 3 ? ",,,\n" : ",,\n";
      continue;
    }
    const auto p = points.point(i);
    out += "," + text::formatNumber(p.x()) + "," + text::formatNumber(p.y());
    if (points.dims() == 3) out += "," + text::formatNumber(p.z());
    out += "\n";
  }
  return out;
}

}  // namespace clm3d
