// clm3d review: the frames of a track worth a look, ranked, each with why, written as CSV; the
// studio's Track page walks the same list (docs/studio-track.md). The options and the run are
// core's (core/track/review_request).
#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/track/review_request.hpp"

namespace clm3d::cli {

void addReviewCommand(CLI::App& root) {
  addRequestCommand(root, "review",
                    "List the frames of a track worth a look, most severe first, each with why: a "
                    "low check or a failed frame, a point that jumps, a point off its moving "
                    "median over time",
                    reviewOptions(), [](const ReviewRequest& request, const CLI::App&) {
                      return runReview(request);
                    });
}

}  // namespace clm3d::cli
