// clm3d demo: runs the whole pipeline on procedural heads, so a new user sees the tool work with
// no data of their own: heads -> renders from the 15 training views with projected,
// visibility-tested landmarks -> a contact sheet -> a 15-view, 3-scale model trained on the heads,
// with its report -> a synthetic test sequence of a held-out head turning through +-60 degrees
// -> tracking it (overlay video with the patches drawn in place) -> the evaluation against the
// exact ground truth, whose summary ends the output. The folder is also a clm3d project (a dataset
// manifest of the heads, the model, the video, its track and ground truth) that clm3d-studio opens.
// The stages are core's (core/demo/demo_pipeline); this file parses, calls them, prints and saves.
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "core/common/data_paths.hpp"
#include "core/dataset/manifest_writer.hpp"
#include "core/demo/demo_pipeline.hpp"
#include "core/eval/eval_plots.hpp"
#include "core/eval/eval_report.hpp"
#include "core/model/model_file.hpp"
#include "core/project/project.hpp"
#include "core/project/project_layout.hpp"
#include "core/track/tracker.hpp"
#include "core/train/report.hpp"
#include "core/train/trainer.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct DemoArgs {
  fs::path out = "demo-out";
  int heads = 8;
  int size = 192;
  int threads = 0;
  int samples = 3;
  double sequenceStep = 2.0;
  std::string optimiser = "fastncc";
  bool real = false;  // also a real face (needs the shared data)
  fs::path realManifest = "resources/datasets/real.json";  // relative to the working folder
};

// The model's name in the project's models folder.
constexpr const char* kModelName = "demo";

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct RealDemo {
  fs::path model, video, tracks;
};

// --real's inputs, checked before the demo starts so a missing one fails at once.
RealDemo findRealInputs(const DemoArgs& args) {
  const std::optional<fs::path> data = sharedDataDir();
  if (!data) {
    throw InputError(
        "demo --real: the shared data was not found (../shared/data beside the repository, or "
        "set CLM3D_DATA); it holds the photos, scans and franck.mp4 the real demo uses");
  }
  RealDemo real;
  real.video = *data / "videos" / "franck.mp4";
  if (!fs::is_regular_file(real.video)) {
    throw InputError("demo --real: " + real.video.string() + ": file not found");
  }
  if (!fs::is_regular_file(args.realManifest)) {
    throw InputError("demo --real: " + args.realManifest.string() +
                     ": dataset manifest not found (run from the repository's root, or give "
                     "--real-manifest)");
  }
  real.model = project_layout::modelFile(args.out, "real");
  return real;
}

// --real: the real-face model of the manifest (LFPW photos among its sources) and franck.mp4 of
// the shared data tracked with it, into the same project, so the studio shows a real person too.
RealDemo runRealDemo(const DemoArgs& args, RealDemo real) {
  std::cerr << "demo: training the real-face model of " << args.realManifest.string()
            << " (minutes)\n";
  TrainSettings settings;
  settings.threads = args.threads;
  const auto trainStart = std::chrono::steady_clock::now();
  CliProgress progress(CliProgress::Style::Tenths, false, "demo: real-face training");
  const ClmModel model =
      trainFromManifest(args.realManifest, settings, CLM3D_VERSION, progress.callback());
  fs::create_directories(real.model.parent_path());
  saveModel(model, real.model);
  std::cout << "demo: trained the real-face model in " << std::setprecision(1)
            << secondsSince(trainStart) << " s: " << real.model.string()
            << "\n  LICENCE: it learnt from LFPW photos, which are for research use only (300-W "
               "terms); the model inherits those terms: do not redistribute it or use it "
               "commercially\n";

  TrackerSettings tracking;
  tracking.fit.optimiser = "rlms";
  real.tracks = project_layout::tracksFile(args.out, real.video, real.model);
  fs::create_directories(real.tracks.parent_path());
  TrackTable tracks;
  CliProgress trackProgress(CliProgress::Style::Tenths, false, "demo: franck.mp4");
  const TrackSummary tracked =
      trackVideo(real.video, model, tracking, tracks, {}, trackProgress.callback());
  writeTrackTable(real.tracks, tracks);
  std::cout << "demo: tracked " << tracked.frames << " frames of " << real.video.string()
            << " with rlms (" << tracked.succeeded << " succeeded, " << tracked.detections
            << " detections): " << real.tracks.string() << '\n';
  return real;
}

void runDemo(const DemoArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const std::optional<RealDemo> realInputs =
      args.real ? std::optional<RealDemo>(findRealInputs(args)) : std::nullopt;
  const fs::path headsDir = args.out / "heads";
  const fs::path rendersDir = args.out / "renders";

  // Procedural heads, written as scans with their manifest.
  std::cerr << "demo: generating " << args.heads << " procedural heads\n";
  const DemoHeads made = writeDemoHeads(
      args.heads, headsDir, {}, [](const WrittenHead& written, const SynthHead& head) {
        std::cerr << "  head " << written.seed << " (" << written.expression
                  << "): " << head.mesh.triangleCount() << " triangles -> " << written.mesh.string()
                  << "\n";
      });

  // Every head from each of the model's training views, the contact sheet of them, and what the
  // renders show about hidden points.
  const auto renderStart = std::chrono::steady_clock::now();
  CliProgress renderProgress(CliProgress::Style::Tenths, false, "demo: rendered views");
  const DemoRenders renders =
      renderDemoViews(made.heads, args.size, args.threads, rendersDir, renderProgress.callback());
  const double renderSeconds = secondsSince(renderStart);
  const fs::path sheet = args.out / "training-views.png";
  writeImage(sheet, demoContactSheet(renders));
  const std::size_t renderCount = renders.renders.size();
  std::cout << "demo: " << made.heads.size() << " heads, " << renderCount << " renders at "
            << args.size << "x" << args.size << " in " << std::fixed << std::setprecision(2)
            << renderSeconds << " s (" << std::setprecision(1)
            << static_cast<double>(renderCount) / renderSeconds << " renders/s on "
            << renders.threads << " threads)\n";
  std::cout << "hidden landmarks of head 1 per view (thesis hidden-point removal):\n"
            << formatHiddenLandmarks(renders, 0);

  // The multi-view model trained on the heads (the thesis's chapter 3), saved with its report.
  const fs::path modelPath = project_layout::modelFile(args.out, kModelName);
  const fs::path reportDir = args.out / "report";
  const TrainSettings settings = demoTrainSettings(args.samples, args.threads);
  const auto trainStart = std::chrono::steady_clock::now();
  // trainModel reports from its worker threads: CliProgress reports one at a time.
  CliProgress trainProgress(CliProgress::Style::Tenths, false, "demo: training");
  const ClmModel model =
      trainDemoModel(made.heads, settings, CLM3D_VERSION, trainProgress.callback());
  fs::create_directories(modelPath.parent_path());
  saveModel(model, modelPath);
  fs::create_directories(reportDir);
  writeTrainingReport(model, reportDir);
  std::cout << "demo: trained a " << model.views.size() << "-view, " << settings.scales
            << "-scale model (" << model.shape.modeCount() << " shape modes) in "
            << std::setprecision(1) << secondsSince(trainStart) << " s: " << modelPath.string()
            << " (" << fs::file_size(modelPath) / 1000000.0
            << " MB); report: " << reportDir.string() << '\n';

  // A held-out head turning frontal -> -60 -> +60 -> frontal (thesis section 5.2).
  std::cerr << "demo: rendering the test sequence of held-out head " << kDemoHeldOutSeed << "\n";
  const DemoSequence sequence = writeDemoSequence(args.sequenceStep, args.out / "sequence");
  const SequenceFiles& files = sequence.files;
  std::cout << "demo: test sequence of " << sequence.summary.frames << " frames ("
            << sequence.settings.width << "x" << sequence.settings.height << ", "
            << sequence.settings.stepDeg << " degrees a frame): " << files.video.string() << '\n';

  // Track it from a face detection on the first frame, drawing the overlay as it goes.
  const fs::path tracksPath = project_layout::tracksFile(args.out, files.video, modelPath);
  fs::create_directories(tracksPath.parent_path());
  const fs::path overlayPath = args.out / "overlay.mp4";
  TrackTable tracks;
  const TrackSummary tracked =
      trackWithOverlay(files.video, model, demoTrackerSettings(args.optimiser), tracks, overlayPath,
                       sequence.settings.width, sequence.settings.height, sequence.settings.fps);
  writeTrackTable(tracksPath, tracks);
  std::cout << "demo: tracked " << tracked.frames << " frames with " << args.optimiser << " ("
            << tracked.succeeded << " succeeded, " << tracked.detections
            << " detections); fit time per frame: median " << std::setprecision(2)
            << tracked.medianMilliseconds() << " ms, 90th percentile "
            << tracked.percentileMilliseconds(0.9) << " ms\n";

  // Evaluate against the exact ground truth (thesis eq. 5.1).
  const EvaluationReport report =
      evaluateTrackFiles(files.truth, {tracksPath}, {args.optimiser}, Scheme::thesis25());
  const fs::path evalDir = args.out / "eval";
  fs::create_directories(evalDir);
  writeReportJson(evalDir / "report.json", report);
  writeEvaluationPlots(evalDir, report);

  std::cout << "demo: done in " << std::setprecision(1) << secondsSince(start)
            << " s. Contact sheet: " << sheet.string() << "; heads: " << headsDir.string()
            << "; renders and projected landmarks: " << rendersDir.string() << '\n';
  // The output folder as a clm3d project, for clm3d-studio.
  Project project;
  project.folder = fs::absolute(args.out);
  project.name = "clm3d demo";
  // Absolute paths: a relative one would be taken as relative to the project folder.
  project.manifest = fs::absolute(args.out / "dataset.json");
  saveManifest(made.manifest, project.manifest);
  project.models = {fs::absolute(modelPath)};
  project.videos = {fs::absolute(files.video)};
  project.tracks = {fs::absolute(tracksPath)};
  project.groundTruth = {fs::absolute(files.truth)};
  saveProject(project);
  if (realInputs) {
    // The synthetic project is saved first, so a failed or interrupted real part leaves it whole.
    const RealDemo real = runRealDemo(args, *realInputs);
    project.models.push_back(fs::absolute(real.model));
    project.videos.push_back(real.video);
    project.tracks.push_back(fs::absolute(real.tracks));
    saveProject(project);
  }

  std::cout << "\n"
            << formatReportText(report) << "\nevaluation plots: " << evalDir.string()
            << "\noverlay video: " << overlayPath.string() << '\n';
  std::cout << "studio project: " << project.file().string()
            << "; open it with: clm3d-studio --demo " << args.out.string() << '\n';
}

}  // namespace

void addDemoCommand(CLI::App& root) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* command = root.add_subcommand(
      "demo",
      "Run the pipeline on procedural heads: generate, render the 15 training views with "
      "projected landmarks and hidden-point tests, train a multi-view model with its report, "
      "render a held-out head turning through +-60 degrees, track it and evaluate the track");
  command->add_option("--out", args->out, "Output folder")->default_val("demo-out");
  command->add_option("--heads", args->heads, "Number of procedural heads to train on")
      ->default_val(8)
      ->check(CLI::Range(1, 50));
  command->add_option("--size", args->size, "Render size in pixels")
      ->default_val(192)
      ->check(CLI::Range(32, 2048));
  command->add_option("--threads", args->threads, "Render threads (0 = one per core)")
      ->default_val(0)
      ->check(CLI::Range(0, 64));
  command->add_option("--samples", args->samples, "Perturbed training renders per head and view")
      ->default_val(3)
      ->check(CLI::Range(1, 20));
  command
      ->add_option("--sequence-step", args->sequenceStep, "Degrees the test head turns per frame")
      ->default_val(2.0)
      ->check(CLI::Range(0.25, 20.0));
  command->add_option("--optimiser", args->optimiser, "Optimiser the tracker uses")
      ->default_val("fastncc");
  command->add_flag("--real", args->real,
                    "Also train the real-face model of --real-manifest (needs ../shared/data or "
                    "$CLM3D_DATA; the model inherits LFPW's research-only terms) and track "
                    "videos/franck.mp4 of the shared data with it into the same project");
  command
      ->add_option("--real-manifest", args->realManifest,
                   "Dataset manifest of the real-face model (with --real)")
      ->default_val("resources/datasets/real.json");
  command->callback([args] { runDemo(*args); });
}

}  // namespace clm3d::cli
