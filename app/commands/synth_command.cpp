// clm3d synth: a synthetic test sequence (thesis section 5.2) with exact ground truth: a scan or a
// procedural head turning, an annotated photo moving in the image plane (or two side by side), or
// a photo's face profiled and turned in 3D. The options and the run are core's
// (core/profile/synth_request); this file adds them, lets Ctrl-C cancel and prints the summary.
#include <string>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "app/commands/option_cli.hpp"
#include "core/profile/synth_request.hpp"

namespace clm3d::cli {

void addSynthCommand(CLI::App& root) {
  addRequestCommand(
      root, "synth",
      "Render a synthetic test sequence (thesis 5.2): a head turning step degrees per frame, with "
      "exact ground-truth landmarks and their visibility",
      synthOptions(), [](SynthRequest& request, const CLI::App& command) {
        request.given = givenOptions(command, synthOptions());
        CliProgress progress(CliProgress::Style::Tenths, false, "synth");
        return runInterruptible("cancelled, no sequence written", [&](CancelToken& cancel) {
          return runSynthRequest(request, progress.callback(), &cancel);
        });
      });
}

}  // namespace clm3d::cli
