// clm3d: the command-line front end. Exit codes: 0 success, 1 bad input (one line on stderr),
// 2 bad usage.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <iostream>

#include "app/commands/commands.hpp"
#include "core/common/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"clm3d: facial landmark detection and tracking with a multi-view 3D CLM", "clm3d"};
  app.set_version_flag("--version", std::string(CLM3D_VERSION));
  app.require_subcommand(1);
  clm3d::cli::addRenderCommand(app);
  clm3d::cli::addSynthHeadCommand(app);
  clm3d::cli::addLandmarksCommand(app);
  clm3d::cli::addDemoCommand(app);
  clm3d::cli::addInfoCommand(app);
  clm3d::cli::addTrainCommand(app);
  clm3d::cli::addSynthCommand(app);
  clm3d::cli::addEvalCommand(app);
  clm3d::cli::addFitCommand(app);
  clm3d::cli::addTrackCommand(app);
  clm3d::cli::addTruthCommand(app);
  clm3d::cli::addReviewCommand(app);
  clm3d::cli::addAdaptCommand(app);
  clm3d::cli::addCorrectionBenchCommand(app);
  clm3d::cli::addFramesCommand(app);
  clm3d::cli::addIctTextureCommand(app);
  clm3d::cli::addEvalPointsCommand(app);
  clm3d::cli::addPlotCommand(app);
  clm3d::cli::addDetectCommand(app);
  clm3d::cli::addBatchCommand(app);
  clm3d::cli::addCalibrateCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (const clm3d::UsageError& e) {  // found by core reading a command's request
    std::cerr << e.what() << "\nRun with --help for more information.\n";
    return 2;
  } catch (const clm3d::Cancelled&) {
    std::cerr << "clm3d: cancelled\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "clm3d: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
