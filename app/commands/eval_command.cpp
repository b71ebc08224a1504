// clm3d eval: trackers' tracks CSVs against ground truth with the error of thesis eq. 5.1
// (docs/evaluation.md). The options and the run are core's (core/eval/eval_request).
#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/eval/eval_request.hpp"

namespace clm3d::cli {

void addEvalCommand(CLI::App& root) {
  addRequestCommand(root, "eval",
                    "Compare tracker outputs (tracks CSV) with ground truth: error of thesis eq. "
                    "5.1, convergence, regions, errors by pose, significance tests and plots",
                    evalOptions(),
                    [](const EvalRequest& request, const CLI::App&) { return runEval(request); });
}

}  // namespace clm3d::cli
