#include "core/demo/demo_run.hpp"

#include <chrono>
#include <iomanip>
#include <optional>
#include <sstream>

#include "core/common/data_paths.hpp"
#include "core/common/error.hpp"
#include "core/dataset/manifest_writer.hpp"
#include "core/demo/detail/demo_pipeline.hpp"
#include "core/eval/calibrated_training.hpp"
#include "core/eval/eval_plots.hpp"
#include "core/eval/eval_report.hpp"
#include "core/model/model_file.hpp"
#include "core/project/project.hpp"
#include "core/project/project_layout.hpp"
#include "core/track/tracker.hpp"
#include "core/train/report.hpp"
#include "core/train/trainer.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {
namespace demo_run_detail {

namespace fs = std::filesystem;
using R = DemoRequest;

std::vector<Option<R>> makeOptions() {
  return {
      textOption<R>(commandOption("out", "Output folder"), &R::out),
      integerOption<R>(commandOption("heads", "Number of procedural heads to train on", 1, 50),
                       &R::heads),
      integerOption<R>(commandOption("size", "Render size in pixels", 32, 2048), &R::size),
      integerOption<R>(commandOption("threads", "Render threads (0 = one per core)", 0, 64),
                       &R::threads),
      integerOption<R>(
          commandOption("samples", "Perturbed training renders per head and view", 1, 20),
          &R::samples),
      realOption<R>(
          commandOption("sequence-step", "Degrees the test head turns per frame", 0.25, 20.0),
          &R::sequenceStep),
      textOption<R>(commandOption("optimiser", "Optimiser the tracker uses"), &R::optimiser),
      flagOption<R>(commandOption("real",
                                  "Also train the real-face model of --real-manifest (needs "
                                  "../shared/data or $CLM3D_DATA; the model inherits LFPW's "
                                  "research-only terms) and track videos/franck.mp4 of the "
                                  "shared data with it into the same project"),
                    &R::real),
      textOption<R>(
          commandOption("real-manifest", "Dataset manifest of the real-face model (with --real)"),
          &R::realManifest),
  };
}

// The model's name in the project's models folder.
constexpr const char* kModelName = "demo";

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct RealDemo {
  fs::path model, video, tracks;
};

// --real's inputs, checked before the demo starts so a missing one fails at once.
RealDemo findRealInputs(const R& args) {
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

// The demo's stdout: one stream, so the number format set for one line carries to the next as
// it always did; each stage's text goes out when the stage ends.
class Speaker {
 public:
  explicit Speaker(const RunReporter& reporter) : reporter_(reporter) {}
  std::ostream& out() { return out_; }
  void flush() {
    reporter_.say(out_.str());
    out_.str("");
  }

 private:
  const RunReporter& reporter_;
  std::ostringstream out_;
};

// --real: the real-face model of the manifest (LFPW photos among its sources) and franck.mp4 of
// the shared data tracked with it, into the same project, so the studio shows a real person too.
RealDemo runRealDemo(const R& args, RealDemo real, const std::string& version,
                     const RunReporter& reporter, Speaker& speaker) {
  reporter.tell("demo: training the real-face model of " + args.realManifest.string() +
                " (minutes)\n");
  TrainSettings settings;
  settings.threads = args.threads;
  const auto trainStart = std::chrono::steady_clock::now();
  const CalibratedTraining trained = trainAndCalibrate(args.realManifest, settings, version,
                                                       reporter.stage("demo: real-face training"));
  const ClmModel& model = trained.model;
  fs::create_directories(real.model.parent_path());
  saveModel(model, real.model);
  speaker.out() << "demo: trained the real-face model in " << std::setprecision(1)
                << secondsSince(trainStart) << " s: " << real.model.string()
                << "\n  LICENCE: it learnt from LFPW photos, which are for research use only "
                   "(300-W terms); the model inherits those terms: do not redistribute it or use "
                   "it commercially\n";
  if (trained.calibration) {
    speaker.out() << "demo: its point check calibrated on the photo pipeline's fits of "
                  << trained.calibration->photos << " annotated photos\n";
  } else if (!trained.calibrationSkipped.empty()) {
    speaker.out() << "demo: warning: calibration photos not used: " << trained.calibrationSkipped
                  << '\n';
  }
  speaker.flush();

  TrackerSettings tracking;
  tracking.fit.optimiser = "rlms";
  real.tracks = project_layout::tracksFile(args.out, real.video, real.model);
  fs::create_directories(real.tracks.parent_path());
  TrackTable tracks;
  const TrackSummary tracked =
      trackVideo(real.video, model, tracking, tracks, {}, reporter.stage("demo: franck.mp4"));
  writeTrackTable(real.tracks, tracks);
  speaker.out() << "demo: tracked " << tracked.frames << " frames of " << real.video.string()
                << " with rlms (" << tracked.succeeded << " succeeded, " << tracked.detections
                << " detections): " << real.tracks.string() << '\n';
  speaker.flush();
  return real;
}

}  // namespace demo_run_detail

const std::vector<Option<DemoRequest>>& demoOptions() {
  static const std::vector<Option<DemoRequest>> table = demo_run_detail::makeOptions();
  return table;
}

void runDemo(const DemoRequest& args, const std::string& version, const RunReporter& reporter) {
  const auto start = std::chrono::steady_clock::now();
  const std::optional<demo_run_detail::RealDemo> realInputs =
      args.real ? std::optional<demo_run_detail::RealDemo>(demo_run_detail::findRealInputs(args))
                : std::nullopt;
  const std::filesystem::path headsDir = args.out / "heads";
  const std::filesystem::path rendersDir = args.out / "renders";
  demo_run_detail::Speaker speaker(reporter);
  std::ostream& out = speaker.out();

  // Procedural heads, written as scans with their manifest.
  reporter.tell("demo: generating " + std::to_string(args.heads) + " procedural heads\n");
  const DemoHeads made = writeDemoHeads(
      args.heads, headsDir, {}, [&reporter](const WrittenHead& written, const SynthHead& head) {
        reporter.tell("  head " + std::to_string(written.seed) + " (" + written.expression +
                      "): " + std::to_string(head.mesh.triangleCount()) + " triangles -> " +
                      written.mesh.string() + "\n");
      });

  // Every head from each of the model's training views, the contact sheet of them, and what the
  // renders show about hidden points.
  const auto renderStart = std::chrono::steady_clock::now();
  const DemoRenders renders = renderDemoViews(made.heads, args.size, args.threads, rendersDir,
                                              reporter.stage("demo: rendered views"));
  const double renderSeconds = demo_run_detail::secondsSince(renderStart);
  const std::filesystem::path sheet = args.out / "training-views.png";
  writeImage(sheet, demoContactSheet(renders));
  const std::size_t renderCount = renders.renders.size();
  out << "demo: " << made.heads.size() << " heads, " << renderCount << " renders at " << args.size
      << "x" << args.size << " in " << std::fixed << std::setprecision(2) << renderSeconds << " s ("
      << std::setprecision(1) << static_cast<double>(renderCount) / renderSeconds
      << " renders/s on " << renders.threads << " threads)\n";
  out << "hidden landmarks of head 1 per view (thesis hidden-point removal):\n"
      << formatHiddenLandmarks(renders, 0);
  speaker.flush();

  // The multi-view model trained on the heads (the thesis's chapter 3), saved with its report.
  const std::filesystem::path modelPath =
      project_layout::modelFile(args.out, demo_run_detail::kModelName);
  const std::filesystem::path reportDir = args.out / "report";
  const TrainSettings settings = demoTrainSettings(args.samples, args.threads);
  const auto trainStart = std::chrono::steady_clock::now();
  const ClmModel model =
      trainDemoModel(made.heads, settings, version, reporter.stage("demo: training"));
  std::filesystem::create_directories(modelPath.parent_path());
  saveModel(model, modelPath);
  std::filesystem::create_directories(reportDir);
  writeTrainingReport(model, reportDir);
  out << "demo: trained a " << model.views.size() << "-view, " << settings.scales
      << "-scale model (" << model.shape.modeCount() << " shape modes) in " << std::setprecision(1)
      << demo_run_detail::secondsSince(trainStart) << " s: " << modelPath.string() << " ("
      << std::filesystem::file_size(modelPath) / 1000000.0 << " MB); report: " << reportDir.string()
      << '\n';
  speaker.flush();

  // A held-out head turning frontal -> -60 -> +60 -> frontal (thesis section 5.2).
  reporter.tell("demo: rendering the test sequence of held-out head " +
                std::to_string(kDemoHeldOutSeed) + "\n");
  const DemoSequence sequence = writeDemoSequence(args.sequenceStep, args.out / "sequence");
  const SequenceFiles& files = sequence.files;
  out << "demo: test sequence of " << sequence.summary.frames << " frames ("
      << sequence.settings.width << "x" << sequence.settings.height << ", "
      << sequence.settings.stepDeg << " degrees a frame): " << files.video.string() << '\n';
  speaker.flush();

  // Track it from a face detection on the first frame, drawing the overlay as it goes.
  const std::filesystem::path tracksPath =
      project_layout::tracksFile(args.out, files.video, modelPath);
  std::filesystem::create_directories(tracksPath.parent_path());
  const std::filesystem::path overlayPath = args.out / "overlay.mp4";
  TrackTable tracks;
  const TrackSummary tracked =
      trackWithOverlay(files.video, model, demoTrackerSettings(args.optimiser), tracks, overlayPath,
                       sequence.settings.width, sequence.settings.height, sequence.settings.fps);
  writeTrackTable(tracksPath, tracks);
  out << "demo: tracked " << tracked.frames << " frames with " << args.optimiser << " ("
      << tracked.succeeded << " succeeded, " << tracked.detections
      << " detections); fit time per frame: median " << std::setprecision(2)
      << tracked.medianMilliseconds() << " ms, 90th percentile "
      << tracked.percentileMilliseconds(0.9) << " ms\n";
  speaker.flush();

  // Evaluate against the exact ground truth (thesis eq. 5.1).
  const EvaluationReport report =
      evaluateTrackFiles(files.truth, {tracksPath}, {args.optimiser}, Scheme::thesis25());
  const std::filesystem::path evalDir = args.out / "eval";
  std::filesystem::create_directories(evalDir);
  writeReportJson(evalDir / "report.json", report);
  writeEvaluationPlots(evalDir, report);

  out << "demo: done in " << std::setprecision(1) << demo_run_detail::secondsSince(start)
      << " s. Contact sheet: " << sheet.string() << "; heads: " << headsDir.string()
      << "; renders and projected landmarks: " << rendersDir.string() << '\n';
  speaker.flush();
  // The output folder as a clm3d project, for clm3d-studio.
  Project project;
  project.folder = std::filesystem::absolute(args.out);
  project.name = "clm3d demo";
  // Absolute paths: a relative one would be taken as relative to the project folder.
  project.manifest = std::filesystem::absolute(args.out / "dataset.json");
  saveManifest(made.manifest, project.manifest);
  project.models = {std::filesystem::absolute(modelPath)};
  project.videos = {std::filesystem::absolute(files.video)};
  project.tracks = {std::filesystem::absolute(tracksPath)};
  project.groundTruth = {std::filesystem::absolute(files.truth)};
  saveProject(project);
  if (realInputs) {
    // The synthetic project is saved first, so a failed or interrupted real part leaves it whole.
    const demo_run_detail::RealDemo real =
        demo_run_detail::runRealDemo(args, *realInputs, version, reporter, speaker);
    project.models.push_back(std::filesystem::absolute(real.model));
    project.videos.push_back(real.video);
    project.tracks.push_back(std::filesystem::absolute(real.tracks));
    saveProject(project);
  }

  out << "\n"
      << formatReportText(report) << "\nevaluation plots: " << evalDir.string()
      << "\noverlay video: " << overlayPath.string() << '\n';
  out << "studio project: " << project.file().string() << "; open it with: clm3d-studio --demo "
      << args.out.string() << '\n';
  speaker.flush();
}

}  // namespace clm3d
