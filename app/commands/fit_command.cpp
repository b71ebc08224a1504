// clm3d fit: the landmarks of one image (--image I --out F) or of many with the model loaded once
// (--images DIR|LIST --out-dir DIR). The files' options and the run are core's (core/track/
// fit_request); the search options are the tracker table's Fit ones (fit_options). Ctrl-C stops a
// batch after the current image.
#include <memory>
#include <optional>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/fit_options.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "app/commands/option_cli.hpp"
#include "core/track/fit_request.hpp"

namespace clm3d::cli {

void addFitCommand(CLI::App& root) {
  auto fit = std::make_shared<FitOptions>();
  CLI::App* command = addRequestCommand(
      root, "fit", "find the landmarks in one image, or in many with the model loaded once",
      fitRequestOptions(), [fit](FitRequest& request, const CLI::App&) {
        request.tracker = fit->tracker;
        std::optional<InterruptScope> interrupt;  // a batch only: one image stops at once
        if (!request.images.empty()) interrupt.emplace();
        CliProgress progress(CliProgress::Style::Lines, request.quiet);
        return runFit(request, progress.callback(), interrupt ? &interrupt->token() : nullptr);
      });
  addFitOptions(*command, *fit, OptionCommand::Fit);
}

}  // namespace clm3d::cli
