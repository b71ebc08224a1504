// clm3d calibrate: a model's point check calibrated on the whole photo pipeline's fits of annotated
// photos. The options and the run are core's (core/eval/calibrate_request); this file adds them,
// shows a progress meter and lets Ctrl-C stop it.
#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "app/commands/option_cli.hpp"
#include "core/eval/calibrate_request.hpp"

namespace clm3d::cli {

void addCalibrateCommand(CLI::App& root) {
  addRequestCommand(root, "calibrate",
                    "Calibrate a model's point check on photo fits: fit annotated photos the "
                    "model did not learn from with the whole still-image pipeline and learn, per "
                    "view, the probability that such a fit is right (docs/fitting.md)",
                    calibrateOptions(), [](const CalibrateRequest& request, const CLI::App&) {
                      InterruptScope interrupt;
                      CliProgress progress(CliProgress::Style::Meter, request.quiet);
                      std::string done =
                          runCalibrate(request, progress.callback(), &interrupt.token());
                      progress.finish();
                      return done;
                    });
}

}  // namespace clm3d::cli
