// Line-chart series from a results table (CSV with a header row): one series per distinct value of
// the grouping columns, x and y from two numeric columns, rows optionally filtered by column
// values. Lets `clm3d plot` draw any study's table (docs/training-data.md) without a plotting
// library.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/eval/eval_plots.hpp"

namespace clm3d {

struct SeriesSelection {
  std::string xColumn;
  std::string yColumn;
  std::vector<std::string> seriesColumns;                  // empty: one series holding every row
  std::vector<std::pair<std::string, std::string>> where;  // keep rows with column == value
};

// Reads a CSV (comma-separated, no quoting, UTF-8 byte-order mark skipped, cells trimmed) and
// groups its rows into series, in order of first appearance; a series' label joins its grouping
// values with ", ". Within a series points are sorted by x. Rows whose y cell is empty or "nan"
// are skipped (a failed run); any other non-numeric x or y is an error. InputError names the file
// (and line): unreadable, no header, unknown column, a row with another cell count, a bad number,
// or no row left to plot.
std::vector<LineSeries> readLineSeriesCsv(const std::filesystem::path& csv,
                                          const SeriesSelection& selection);

}  // namespace clm3d
