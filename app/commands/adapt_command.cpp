// clm3d adapt: a model adapted to the person of one video from its corrected frames
// (docs/adapt.md). The options and the run are core's (core/track/adapt_request); progress goes to
// stderr and Ctrl-C cancels without writing the model.
#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "app/commands/option_cli.hpp"
#include "core/track/adapt_request.hpp"

namespace clm3d::cli {

void addAdaptCommand(CLI::App& root) {
  addRequestCommand(root, "adapt",
                    "Adapt a model to the person of one video: its patch experts and template "
                    "means learn from the video's corrected frames, the general model kept as "
                    "their prior",
                    adaptRequestOptions(), [](const AdaptRequest& request, const CLI::App&) {
                      InterruptScope interrupt;
                      CliProgress progress(CliProgress::Style::Tenths, request.quiet, "adapt");
                      return runAdapt(request, progress.callback(), &interrupt.token());
                    });
}

}  // namespace clm3d::cli
