// clm3d frames: a video's frames as numbered images (frame_000042.png), named like the per-frame
// .pts of `clm3d truth --pts`. The options and the run are core's (core/track/frames_request);
// this file adds them, shows a progress meter and lets Ctrl-C stop it.
#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "app/commands/option_cli.hpp"
#include "core/track/frames_request.hpp"

namespace clm3d::cli {

void addFramesCommand(CLI::App& root) {
  addRequestCommand(root, "frames",
                    "Write a video's frames as numbered images (frame_000042.png), named like the "
                    "per-frame .pts of `clm3d truth --pts`, for tools that read images",
                    framesOptions(), [](const FramesRequest& request, const CLI::App&) {
                      InterruptScope interrupt;
                      CliProgress progress(CliProgress::Style::Meter, request.quiet);
                      std::string done =
                          runFrames(request, progress.callback(), &interrupt.token());
                      progress.finish();
                      return done;
                    });
}

}  // namespace clm3d::cli
