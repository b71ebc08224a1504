// clm3d eval-points: fitted points against a mark-up, one image or folders paired by file stem,
// with the error of thesis eq. 5.1 (docs/evaluation.md). The options and the run are core's
// (core/eval/eval_points_request).
#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/eval/eval_points_request.hpp"

namespace clm3d::cli {

void addEvalPointsCommand(CLI::App& root) {
  addRequestCommand(root, "eval-points",
                    "Compare point files of one image (e.g. a fit with a hand mark-up), or folders "
                    "of them paired by file stem: error of thesis eq. 5.1 over chosen points, "
                    "normalised by the true eye-centre distance",
                    evalPointsOptions(), [](const EvalPointsRequest& request, const CLI::App&) {
                      return runEvalPoints(request);
                    });
}

}  // namespace clm3d::cli
