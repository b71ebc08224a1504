// What `clm3d plot` is asked for, described once as an option table (the CLI builds the command's
// options from it), and its run: a line chart (PNG) from a results table, one line per series
// (core/eval/line_series_csv, drawn by core/eval/eval_plots as the evaluation's plots are).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/option_table.hpp"
#include "core/eval/eval_plots.hpp"
#include "core/eval/line_series_csv.hpp"

namespace clm3d {

struct PlotRequest {
  std::filesystem::path csv, out;
  SeriesSelection selection;
  std::vector<std::string> where;  // COLUMN=VALUE
  LinePlotOptions options;
  bool yFromData = false;
};

// Every option of `clm3d plot`, in its help's order.
const std::vector<Option<PlotRequest>>& plotOptions();

// Draws and writes the chart; returns what the command prints (the file and its series).
std::string runPlot(PlotRequest request);

}  // namespace clm3d
