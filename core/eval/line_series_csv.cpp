#include "core/eval/line_series_csv.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string_view>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

std::string trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) {
    text.remove_suffix(1);
  }
  return std::string(text);
}

std::vector<std::string> splitCells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(trimmed(std::string_view(line).substr(
        start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

// True and the value if cell is a finite number (the whole cell).
bool parseNumber(const std::string& cell, double& value) {
  if (cell.empty()) return false;
  char* end = nullptr;
  value = std::strtod(cell.c_str(), &end);
  return end == cell.c_str() + cell.size() && std::isfinite(value);
}

bool isMissing(const std::string& cell) {
  std::string lower = cell;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.empty() || lower == "nan" || lower == "na" || lower == "n/a";
}

}  // namespace

std::vector<LineSeries> readLineSeriesCsv(const std::filesystem::path& csv,
                                          const SeriesSelection& selection) {
  std::ifstream in(csv);
  if (!in) throwInputError(csv, "cannot open the table");
  std::string line;
  if (!std::getline(in, line)) throwInputError(csv, "empty file: no header row");
  if (line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
  const auto header = splitCells(line);
  const auto column = [&](const std::string& name, const char* role) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) {
      throwInputError(csv, std::string("no column '") + name + "' (" + role + ")", 1);
    }
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t xIndex = column(selection.xColumn, "x");
  const std::size_t yIndex = column(selection.yColumn, "y");
  std::vector<std::size_t> groupIndices;
  for (const auto& name : selection.seriesColumns) groupIndices.push_back(column(name, "series"));
  std::vector<std::pair<std::size_t, std::string>> filters;
  for (const auto& [name, value] : selection.where)
    filters.push_back({column(name, "where"), value});

  std::vector<LineSeries> series;
  std::map<std::string, std::size_t> byLabel;
  int lineNumber = 1;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (trimmed(line).empty()) continue;
    const auto cells = splitCells(line);
    if (cells.size() != header.size()) {
      throwInputError(
          csv,
          std::to_string(cells.size()) + " cells, the header has " + std::to_string(header.size()),
          lineNumber);
    }
    if (!std::all_of(filters.begin(), filters.end(),
                     [&](const auto& f) { return cells[f.first] == f.second; })) {
      continue;
    }
    if (isMissing(cells[yIndex])) continue;
    double x = 0.0, y = 0.0;
    if (!parseNumber(cells[xIndex], x)) {
      throwInputError(csv,
                      "column " + selection.xColumn + ": '" + cells[xIndex] + "' is not a number",
                      lineNumber);
    }
    if (!parseNumber(cells[yIndex], y)) {
      throwInputError(csv,
                      "column " + selection.yColumn + ": '" + cells[yIndex] + "' is not a number",
                      lineNumber);
    }
    std::string label;
    for (const std::size_t g : groupIndices) label += (label.empty() ? "" : ", ") + cells[g];
    const auto [it, added] = byLabel.try_emplace(label, series.size());
    if (added) series.push_back({label, {}});
    series[it->second].points.push_back({x, y});
  }
  if (series.empty()) throwInputError(csv, "no row to plot (after the filters)");
  for (auto& s : series) {
    std::stable_sort(s.points.begin(), s.points.end(),
                     [](const cv::Point2d& a, const cv::Point2d& b) { return a.x < b.x; });
  }
  return series;
}

}  // namespace clm3d
