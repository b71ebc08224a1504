#include "core/eval/plot_request.hpp"

#include <stdexcept>

#include "core/common/error.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {
namespace plot_request_detail {

using R = PlotRequest;

std::vector<Option<R>> makeOptions() {
  const auto text = [](const char* name, const char* help, auto field) {
    return textOption<R>(commandOption(name, help), field);
  };
  const auto required = [](const char* name, const char* help, auto field) {
    return textOption<R>(requiredOption(name, help), field);
  };
  return {
      required("csv", "Table with a header row", &R::csv),
      required("out", "PNG to write", &R::out),
      required(
          "x", "Column of the x values", [](R & r) -> auto& { return r.selection.xColumn; }),
      required(
          "y", "Column of the y values", [](R & r) -> auto& { return r.selection.yColumn; }),
      textListOption<R>(
          commandOption("series",
                        "Column(s) whose values name a line (repeat for "
                        "several; default: one line)"),
          [](R & r) -> auto& { return r.selection.seriesColumns; }),
      textListOption<R>(
          commandOption("where", "Keep only rows with COLUMN=VALUE (repeat: all must hold)"),
          &R::where),
      text(
          "title", "Title above the chart", [](R & r) -> auto& { return r.options.title; }),
      text(
          "x-label", "x axis label (default: the column)",
          [](R & r) -> auto& { return r.options.xLabel; }),
      text(
          "y-label", "y axis label (default: the column)",
          [](R & r) -> auto& { return r.options.yLabel; }),
      flagOption<R>(
          commandOption("log-x", "Logarithmic x axis"),
          [](R & r) -> auto& { return r.options.logX; }),
      flagOption<R>(
          commandOption("y-from-data", "Start the y axis at the data's minimum instead of 0"),
          &R::yFromData),
  };
}

}  // namespace plot_request_detail

const std::vector<Option<PlotRequest>>& plotOptions() {
  static const std::vector<Option<PlotRequest>> table = plot_request_detail::makeOptions();
  return table;
}

std::string runPlot(PlotRequest args) {
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
  return "plot: " + args.out.string() + " (" + std::to_string(series.size()) + " series)\n";
}

}  // namespace clm3d
