// clm3d track: the landmarks tracked through a video into the per-frame CSV (docs/tracks-csv.md)
// and optionally the overlay video. The files' options and the run are core's (core/track/
// track_request); the search and tracker options are the tracker table's Track ones
// (fit_options). Progress goes to stderr; Ctrl-C stops and keeps the frames tracked so far.
#include <atomic>
#include <memory>
#include <string>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/fit_options.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "app/commands/option_cli.hpp"
#include "core/track/track_request.hpp"

namespace clm3d::cli {

void addTrackCommand(CLI::App& root) {
  auto fit = std::make_shared<FitOptions>();
  CLI::App* command = addRequestCommand(
      root, "track", "track the landmarks through a video", trackRequestOptions(),
      [fit](TrackRequest& request, const CLI::App&) {
        request.tracker = fit->tracker;
        InterruptScope interrupt;
        std::atomic<std::size_t> written{0};
        CliProgress progress(CliProgress::Style::Meter, request.quiet);
        progress.setDetail([&written] { return "(" + std::to_string(written) + " frames)"; });
        return runTrack(
            request, progress.callback(), [&written](std::size_t rows) { written = rows; },
            &interrupt.token());
      });
  addFitOptions(*command, *fit, OptionCommand::Track);
}

}  // namespace clm3d::cli
