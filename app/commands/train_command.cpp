// clm3d train: trains a multi-view 3D CLM (or, with --single-view, the 2D baseline) from a
// dataset manifest and writes the model file; optionally the report pictures. Ctrl-C cancels
// cleanly: the model is written atomically at the very end, so no half-written file remains.
#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <sstream>

#include "app/commands/commands.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "core/common/error.hpp"
#include "core/model/model_file.hpp"
#include "core/train/report.hpp"
#include "core/train/trainer.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct TrainArgs {
  fs::path dataset, out, report;
  TrainSettings settings;
  bool noMirror = false;
  bool noAugmentation = false;
  int samples = 5;
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
  args.settings.mirrorRightViews = !args.noMirror;
  args.settings.samplesPerView = args.samples;
  args.settings.augmentationFromManifest = !args.noAugmentation;
  InterruptScope interrupt;
  const auto start = std::chrono::steady_clock::now();
  std::mutex printMutex;
  int lastDecile = -1;
  const auto progress = [&](double fraction, std::string_view stage) {
    const int decile = static_cast<int>(fraction * 10.0 + 1e-9);
    std::lock_guard lock(printMutex);
    if (decile <= lastDecile) return;
    lastDecile = decile;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::ostringstream line;
    line << "train: " << std::setw(3) << decile * 10 << "% " << stage << ", " << std::fixed
         << std::setprecision(1) << elapsed << " s";
    if (fraction > 0.05 && fraction < 1.0)
      line << ", ~" << elapsed * (1 - fraction) / fraction << " s left";
    std::cerr << line.str() << '\n';
  };
  try {
    std::vector<PhotoPlacement> placements;
    ClmModel model = trainFromManifest(args.dataset, args.settings, std::string(CLM3D_VERSION),
                                       progress, &interrupt.token(), &placements);
    if (!placements.empty()) {
      int used = 0;
      int copies = 0;
      for (const PhotoPlacement& placed : placements) {
        used += placed.samples > 0 ? 1 : 0;
        copies += placed.samples;
        if (!placed.skipped.empty()) {
          std::cerr << "train: photo " << placed.id << " skipped: " << placed.skipped << '\n';
        }
      }
      std::cerr << "train: " << used << " of " << placements.size() << " photos used (" << copies
                << " samples with the mirror images); a model trained on photos inherits their "
                   "licence terms\n";
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
  command->add_option("--threads", args->settings.threads, "Worker threads (0 = one per core)")
      ->check(CLI::Range(0, 64));
  command->add_option("--seed", args->settings.seed, "Random seed (same seed, same model)");
  command->add_flag("--single-view", args->settings.singleView,
                    "Train the single-view 2D baseline (frontal texture model, 2D shape model)");
  command->add_option("--views-yaw", args->settings.yawsDeg, "View yaw centres in degrees")
      ->delimiter(',');
  command->add_option("--views-pitch", args->settings.pitchesDeg, "View pitch centres in degrees")
      ->delimiter(',');
  command->add_option("--scales", args->settings.scales, "Pyramid scales per view")
      ->check(CLI::Range(1, 5));
  command->add_option("--patch-size", args->settings.patchSize, "Patch size in pixels")
      ->check(CLI::Range(4, 64));
  command->add_option("--samples", args->samples, "Perturbed renders per subject and view")
      ->check(CLI::Range(1, 100));
  command
      ->add_option("--view-coverage", args->settings.perturbation.viewCoverage,
                   "Share of half the spacing of the view centres that the pitch/yaw jitter of "
                   "each view's renders covers (0 = +-5 degrees only)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.5));
  command
      ->add_option("--texture-variance", args->settings.textureVariance,
                   "Variance kept by each patch PCA")
      ->check(CLI::Range(0.01, 1.0));
  command
      ->add_option("--shape-variance", args->settings.shape.varianceKept,
                   "Variance kept by the shape PCA")
      ->check(CLI::Range(0.01, 1.0));
  command->add_flag("--no-mirror", args->noMirror,
                    "Render the right-side views instead of mirroring");
  command->add_flag("--no-augmentation", args->noAugmentation,
                    "Switch off all appearance augmentation for this run, the default cluttered "
                    "background included: renders on flat black");
  command->add_flag("--mirror-shapes", args->settings.shape.mirror,
                    "Add a left/right mirrored copy of every training shape to the shape model");
  command
      ->add_option("--shape-limit", args->settings.shape.limitSd,
                   "Shape parameter limit in standard deviations")
      ->default_val(3.0)
      ->check(CLI::Range(0.5, 10.0));
  command
      ->add_option("--texture-max-modes", args->settings.textureMaxModes,
                   "At most this many modes per patch PCA (0 = no cap; smaller models)")
      ->default_val(0)
      ->check(CLI::Range(0, 1000));
  command
      ->add_option("--hidden-share", args->settings.hiddenShare,
                   "A landmark hidden in more than this share of a view's renders is left out of "
                   "the view (1 = keep every landmark: hidden-point removal off)")
      ->default_val(0.5)
      ->check(CLI::Range(0.0, 1.0));
  command
      ->add_option("--expert-radius", args->settings.expertRadius,
                   "Train a discriminative patch expert per landmark, view and scale from "
                   "displacements of up to this many pixels (0 = none: a model for the template "
                   "optimisers only; rlms needs experts)")
      ->default_val(args->settings.expertRadius)
      ->check(CLI::Range(0, 16));
  command
      ->add_option("--expert-ridge", args->settings.expertRidge,
                   "Ridge weight of the experts' regression, relative to the data's mean variance")
      ->default_val(args->settings.expertRidge)
      ->check(CLI::Range(1e-4, 100.0));
  command
      ->add_option("--expert-units", args->settings.expertUnits,
                   "Units of each patch expert: 1 = a linear filter with a logistic output, more = "
                   "a small neural field (units' sigmoid responses summed)")
      ->default_val(args->settings.expertUnits)
      ->check(CLI::Range(1, 16));
  command
      ->add_option("--photo-jitter", args->settings.photoJitter,
                   "Perturbed placements (scale, roll, shift) of each training photo beside its "
                   "exact one")
      ->default_val(args->settings.photoJitter)
      ->check(CLI::Range(0, 20));
  command->callback([args] { runTrain(*args); });
}

}  // namespace clm3d::cli
