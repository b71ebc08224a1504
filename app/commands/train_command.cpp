// clm3d train: trains a multi-view 3D CLM (or, with --single-view, the 2D baseline) from a
// dataset manifest (and, when it names calibration photos, calibrates the point check on the photo
// pipeline's fits of them) and writes the model file; optionally the report pictures. Ctrl-C
// cancels cleanly: the model is written atomically at the very end, so no half-written file
// remains.
#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "app/commands/option_cli.hpp"
#include "core/common/error.hpp"
#include "core/eval/calibrated_training.hpp"
#include "core/model/model_file.hpp"
#include "core/train/report.hpp"
#include "core/train/train_options.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct TrainArgs {
  fs::path dataset, out, report;
  TrainSettings settings;  // filled by the options of core/train/train_options
};

// Prints the model summary the issue asks for: views, modes per view/scale, patches per view.
void printSummary(const ClmModel& model, const fs::path& out, double seconds) {
  std::cout << "trained " << (model.singleView ? "single-view 2D baseline" : "multi-view 3D CLM")
            << " in " << std::fixed << std::setprecision(1) << seconds << " s -> " << out.string()
            << " (" << std::setprecision(2) << static_cast<double>(fs::file_size(out)) / 1e6
            << " MB)\n";
  double shapeTotal = model.shape.variances.sum();
  std::cout << "shape model: " << model.shape.dims << "D, " << model.shape.modeCount() << " modes ("
            << std::setprecision(4) << shapeTotal << " mm^2 total variance kept)\n";
  std::cout << "views (pitch, yaw): landmarks (patches per view), texture modes per scale\n";
  for (const ViewModel& view : model.views) {
    std::cout << "  " << std::showpos << std::setw(4) << static_cast<int>(view.pitchDeg) << " "
              << std::setw(4) << static_cast<int>(view.yawDeg) << std::noshowpos << "  "
              << (view.scales.empty() ? 0 : view.scales[0].landmarks.size()) << " visible, modes";
    for (const PatchModel& scale : view.scales) std::cout << " " << scale.pca.modeCount();
    std::cout << (view.mirrored ? "  (mirrored)" : "") << '\n';
  }
}

void runTrain(TrainArgs& args) {
  InterruptScope interrupt;
  const auto start = std::chrono::steady_clock::now();
  CliProgress progress(CliProgress::Style::Tenths, false, "train");
  try {
    CalibratedTraining trained =
        trainAndCalibrate(args.dataset, args.settings, std::string(CLM3D_VERSION),
                          progress.callback(), &interrupt.token());
    const ClmModel& model = trained.model;
    const TrainingDetails& details = trained.details;
    const std::vector<PhotoPlacement>& placements = details.placements;
    if (!placements.empty()) {
      int used = 0;
      int copies = 0;
      int capped = 0;
      for (const PhotoPlacement& placed : placements) {
        used += placed.samples > 0 ? 1 : 0;
        copies += placed.samples;
        capped += placed.samples == 0 && placed.capped > 0 ? 1 : 0;
        if (!placed.skipped.empty()) {
          std::cerr << "train: photo " << placed.id << " skipped: " << placed.skipped << '\n';
        }
      }
      std::cerr << "train: " << used << " of " << placements.size() << " photos used (" << copies
                << " samples with the mirror images"
                << (capped > 0 ? ", " + std::to_string(capped) +
                                     " left out as their views were full (per_view)"
                               : std::string())
                << "); a model trained on photos inherits their licence terms\n";
    }
    if (!details.calibration.empty()) {
      std::cerr << formatViewCalibration(model, details.calibration);
    }
    if (trained.calibration) {
      std::cerr << "train: the point check calibrated on the photo pipeline's fits of "
                << formatPhotoFitCalibration(*trained.calibration, trained.calibrationSettings);
    } else if (!trained.calibrationSkipped.empty()) {
      std::cerr << "train: warning: calibration_photos not used: " << trained.calibrationSkipped
                << "; the model keeps the check's own probability\n";
    }
    interrupt.token().throwIfCancelled();
    std::cerr << "train: saving\n";
    saveModel(model, args.out);
    interrupt.release();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    printSummary(model, args.out, seconds);
    if (!args.report.empty()) {
      const auto files = writeTrainingReport(model, args.report);
      std::cout << "report: " << files.size() << " pictures in " << args.report.string() << '\n';
    }
  } catch (const Cancelled&) {
    throw Error("cancelled, no model written");
  }
}

}  // namespace

void addTrainCommand(CLI::App& root) {
  auto args = std::make_shared<TrainArgs>();
  CLI::App* command = root.add_subcommand(
      "train",
      "Train a multi-view 3D CLM (or the single-view 2D baseline) from a dataset manifest");
  command->add_option("--dataset", args->dataset, "Dataset manifest (JSON)")->required();
  command->add_option("--out", args->out, "Model file to write (.clm3d)")->required();
  command->add_option("--report", args->report, "Folder for the report pictures");
  // Every training setting, from the one table the studio's form and TrainSettings::validate
  // use too (names, help, defaults, ranges).
  addTableOptions(*command, trainOptions(), OptionCommand::Train, args->settings);
  command->callback([args] { runTrain(*args); });
}

}  // namespace clm3d::cli
