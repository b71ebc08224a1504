// The subcommands of the clm3d command line. Each adds itself to the root app with its options
// and a callback that does the work through core; errors propagate as clm3d::Error.
#pragma once

#include <CLI/CLI.hpp>

namespace clm3d::cli {

void addRenderCommand(CLI::App& root);
void addSynthHeadCommand(CLI::App& root);
void addLandmarksCommand(CLI::App& root);
void addDemoCommand(CLI::App& root);
void addInfoCommand(CLI::App& root);
void addTrainCommand(CLI::App& root);
void addSynthCommand(CLI::App& root);
void addEvalCommand(CLI::App& root);
void addFitCommand(CLI::App& root);
void addTrackCommand(CLI::App& root);
void addTruthCommand(CLI::App& root);
void addReviewCommand(CLI::App& root);
void addAdaptCommand(CLI::App& root);
void addCorrectionBenchCommand(CLI::App& root);
void addFramesCommand(CLI::App& root);
void addIctTextureCommand(CLI::App& root);
void addEvalPointsCommand(CLI::App& root);
void addPlotCommand(CLI::App& root);
void addDetectCommand(CLI::App& root);
void addBatchCommand(CLI::App& root);
void addCalibrateCommand(CLI::App& root);

}  // namespace clm3d::cli
