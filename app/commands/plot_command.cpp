// clm3d plot: a line chart (PNG) from a results table (CSV): x and y columns, one line per distinct
// value of the series columns, rows filtered by --where; drawn by core/eval/eval_plots like the
// evaluation's plots, so studies need no plotting library (docs/training-data.md).
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "core/common/error.hpp"
#include "core/eval/eval_plots.hpp"
#include "core/eval/line_series_csv.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct PlotArgs {
  fs::path csv;
  fs::path out;
  SeriesSelection selection;
  std::vector<std::string> where;
  LinePlotOptions options;
  bool yFromData = false;
};

void runPlot(PlotArgs args) {
  for (const auto& condition : args.where) {
    const auto equals = condition.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw InputError("--where '" + condition + "': expected COLUMN=VALUE");
    }
    args.selection.where.push_back({condition.substr(0, equals), condition.substr(equals + 1)});
  }
  const auto series = readLineSeriesCsv(args.csv, args.selection);
  if (args.options.xLabel.empty()) args.options.xLabel = args.selection.xColumn;
  if (args.options.yLabel.empty()) args.options.yLabel = args.selection.yColumn;
  args.options.yFromZero = !args.yFromData;
  cv::Mat image;
  try {
    image = plotLines(series, args.options);
  } catch (const std::invalid_argument& e) {
    throwInputError(args.csv, e.what());
  }
  writeImage(args.out, image);
  std::cout << "plot: " << args.out.string() << " (" << series.size() << " series)\n";
}

}  // namespace

void addPlotCommand(CLI::App& root) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* command = root.add_subcommand(
      "plot", "Draw a line chart (PNG) from a CSV table: one line per series, y against x");
  command->add_option("--csv", args->csv, "Table with a header row")->required();
  command->add_option("--out", args->out, "PNG to write")->required();
  command->add_option("--x", args->selection.xColumn, "Column of the x values")->required();
  command->add_option("--y", args->selection.yColumn, "Column of the y values")->required();
  command->add_option("--series", args->selection.seriesColumns,
                      "Column(s) whose values name a line (repeat for several; default: one line)");
  command->add_option("--where", args->where,
                      "Keep only rows with COLUMN=VALUE (repeat: all must hold)");
  command->add_option("--title", args->options.title, "Title above the chart");
  command->add_option("--x-label", args->options.xLabel, "x axis label (default: the column)");
  command->add_option("--y-label", args->options.yLabel, "y axis label (default: the column)");
  command->add_flag("--log-x", args->options.logX, "Logarithmic x axis");
  command->add_flag("--y-from-data", args->yFromData,
                    "Start the y axis at the data's minimum instead of 0");
  command->callback([args] { runPlot(*args); });
}

}  // namespace clm3d::cli
