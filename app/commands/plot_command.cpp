// clm3d plot: a line chart (PNG) from a results table (CSV), one line per series, so studies need
// no plotting library (docs/training-data.md). The options and the run are core's
// (core/eval/plot_request).
#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/eval/plot_request.hpp"

namespace clm3d::cli {

void addPlotCommand(CLI::App& root) {
  addRequestCommand(
      root, "plot", "Draw a line chart (PNG) from a CSV table: one line per series, y against x",
      plotOptions(), [](const PlotRequest& request, const CLI::App&) { return runPlot(request); });
}

}  // namespace clm3d::cli
