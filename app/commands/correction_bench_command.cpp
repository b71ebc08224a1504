// clm3d correction-bench: issue 29's correction benchmark, a simulated annotator cleaning tracked
// sequences against their truth in frame order, in the review list's order and with the model
// adapted as it goes (docs/studio-track.md). The options and the run are core's
// (core/eval/correction_bench_request); progress goes to stderr and Ctrl-C cancels.
#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "app/commands/option_cli.hpp"
#include "core/eval/correction_bench_request.hpp"

namespace clm3d::cli {

void addCorrectionBenchCommand(CLI::App& root) {
  addRequestCommand(root, "correction-bench",
                    "Count the frames and drags a simulated annotator needs to bring every frame "
                    "of tracked sequences within a tolerance of their truth: in frame order, in "
                    "the review list's order, and with the model adapted every few corrections",
                    correctionBenchOptions(),
                    [](const CorrectionBenchRequest& request, const CLI::App&) {
                      InterruptScope interrupt;
                      CliProgress progress(CliProgress::Style::Meter, request.quiet);
                      return runCorrectionBench(request, progress.callback(), &interrupt.token());
                    });
}

}  // namespace clm3d::cli
