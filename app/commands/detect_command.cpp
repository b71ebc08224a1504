// clm3d detect: face detectors measured on annotated photos (faces found, wrong faces picked, no
// face, time per image; the box calibration and the start error). The options and the run are
// core's (core/eval/detect_request); this file adds them and prints a line per image on stderr.
#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/eval/detect_request.hpp"

namespace clm3d::cli {

void addDetectCommand(CLI::App& root) {
  addRequestCommand(root, "detect",
                    "Measure face detectors on annotated photos: annotated faces found, wrong "
                    "faces picked, no face, time per image; the box calibration (--calibrate) and "
                    "the start error (--model --start-error)",
                    detectOptions(), [](const DetectRequest& request, const CLI::App&) {
                      CliProgress progress(CliProgress::Style::Lines, request.quiet);
                      return runDetect(request, progress.callback());
                    });
}

}  // namespace clm3d::cli
