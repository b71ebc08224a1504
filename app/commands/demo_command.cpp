// clm3d demo: runs the whole pipeline on procedural heads, so a new user sees the tool work with
// no data of their own: heads -> renders from the 15 training views with projected,
// visibility-tested landmarks -> a contact sheet -> a 15-view, 3-scale model trained on the heads,
// with its report -> a synthetic test sequence of a held-out head turning through +-60 degrees
// -> tracking it (overlay video with the patches drawn in place) -> the evaluation against the
// exact ground truth, whose summary ends the output. The folder is also a clm3d project (a dataset
// manifest of the heads, the model, the video, its track and ground truth) that clm3d-studio opens.
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <sstream>
#include <vector>

#include "app/commands/commands.hpp"
#include "core/common/data_paths.hpp"
#include "core/common/decile_progress.hpp"
#include "core/common/parallel_for.hpp"
#include "core/dataset/manifest_writer.hpp"
#include "core/eval/eval_plots.hpp"
#include "core/eval/eval_report.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "core/geometry/projection.hpp"
#include "core/mesh/mesh_export.hpp"
#include "core/model/model_file.hpp"
#include "core/project/project.hpp"
#include "core/project/project_layout.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/synth/synth_head.hpp"
#include "core/track/fit_overlay.hpp"
#include "core/track/tracker.hpp"
#include "core/train/report.hpp"
#include "core/train/trainer.hpp"
#include "core/video/video_writer.hpp"
#include "core/viz/contact_sheet.hpp"
#include "core/viz/image_file.hpp"
#include "core/viz/landmark_overlay.hpp"

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

// The held-out head of the test sequence: a seed none of the training heads uses.
constexpr std::uint64_t kHeldOutSeed = 1000;

// The model's name in the project's models folder.
constexpr const char* kModelName = "demo";

struct RenderedView {
  cv::Mat overlay;
  int hidden = 0;
  std::string hiddenNames;
};

RenderedView renderView(OffscreenRenderer& renderer, const SynthHead& head, const ViewCentre& view,
                        int size, const fs::path& stem) {
  const Scheme& scheme = Scheme::thesis25();
  // Frame the face, not the whole head: the landmarks (earlobes included) span ~85% of the image.
  const Eigen::Matrix3Xd points = head.landmarks.matrix();
  const Eigen::Vector3d centroid = points.rowwise().mean();
  const double radius = (points.colwise() - centroid).colwise().norm().maxCoeff();
  Camera camera = Camera::fromVerticalFov(size, size, 30.0);
  Pose pose = Pose::fromDegrees(view.pitchDeg, view.yawDeg, 0.0);
  pose.translation = -(pose.rotation() * centroid);
  pose.translation.z() += distanceToFit(radius, camera, 0.85);
  camera = Camera::fromVerticalFov(size, size, 30.0, 10.0, -pose.translation.z() + 400.0);
  const RenderResult result = renderer.render(pose, camera);

  LandmarkSet projected(head.landmarks.size(), 2);
  std::vector<bool> visible(static_cast<std::size_t>(head.landmarks.size()));
  RenderedView rendered;
  for (int i = 0; i < head.landmarks.size(); ++i) {
    const Eigen::Vector3d model = head.landmarks.point(i);
    projected.set(i, Eigen::Vector2d(projectPoint(model, pose, camera)));
    visible[static_cast<std::size_t>(i)] = result.isVisible(model);
    if (!visible[static_cast<std::size_t>(i)]) {
      ++rendered.hidden;
      rendered.hiddenNames += (rendered.hiddenNames.empty() ? "" : ", ") + scheme.id(i);
    }
  }
  writeImage(stem.string() + ".png", result.bgra);
  writeLandmarks(stem.string() + ".pts", projected, scheme);
  rendered.overlay = result.bgra.clone();
  drawLandmarks(rendered.overlay, projected, visible, scheme, {false, 1.0});
  return rendered;
}

std::string viewName(const ViewCentre& view) {
  std::ostringstream name;
  name << "yaw" << std::showpos << static_cast<int>(view.yawDeg) << "_pitch"
       << static_cast<int>(view.pitchDeg);
  return name.str();
}

// Progress lines on stderr at every tenth, safe to call from the workers.
DecileProgress stderrProgress(const std::string& what) {
  return DecileProgress(
      [what](int percent, std::string_view stage) {
        std::cerr << "demo: " << what << (stage.empty() ? "" : " ") << stage << " " << percent
                  << "%\n";
      },
      true);
}

struct DemoHeads {
  std::vector<SynthHead> heads;
  DatasetManifest manifest;  // the heads as scans, for the studio's annotate and train pages
};

DemoHeads makeHeads(const DemoArgs& args, const fs::path& headsDir) {
  const std::vector<std::string> expressions = expressionPresetNames();
  const Scheme& scheme = Scheme::thesis25();
  std::cerr << "demo: generating " << args.heads << " procedural heads\n";
  DemoHeads made;
  made.manifest.name = "clm3d-demo-heads";
  for (int i = 0; i < args.heads; ++i) {
    const auto seed = static_cast<std::uint64_t>(i + 1);
    const std::string& expression = expressions[static_cast<std::size_t>(i) % expressions.size()];
    made.heads.push_back(generateHead(seed, Expression::preset(expression)));
    const std::string name = "head-" + std::to_string(seed);
    const fs::path mesh = headsDir / (name + ".obj");
    const fs::path landmarks = headsDir / (name + ".ljson");
    saveObj(made.heads.back().mesh, mesh);
    writeLandmarks(landmarks, made.heads.back().landmarks, scheme);
    made.manifest.scans.push_back({fs::absolute(mesh), fs::absolute(landmarks), name, expression});
    std::cerr << "  head " << seed << " (" << expression
              << "): " << made.heads.back().mesh.triangleCount() << " triangles -> "
              << mesh.string() << "\n";
  }
  return made;
}

// Every head from each of the model's training views (one renderer per head), the contact sheet
// of them, and what the renders show about hidden points.
void renderTrainingViews(const DemoArgs& args, const std::vector<SynthHead>& heads,
                         const fs::path& rendersDir, const fs::path& sheet) {
  const std::vector<ViewCentre> views = TrainSettings{}.views();
  const int viewCount = static_cast<int>(views.size());
  const int jobs = static_cast<int>(heads.size()) * viewCount;
  std::vector<RenderedView> rendered(static_cast<std::size_t>(jobs));
  DecileProgress progress = stderrProgress("rendered views");
  std::mutex doneMutex;
  int done = 0;
  const auto renderStart = std::chrono::steady_clock::now();
  parallelFor(static_cast<int>(heads.size()), args.threads, [&](int head) {
    const SynthHead& subject = heads[static_cast<std::size_t>(head)];
    OffscreenRenderer renderer(subject.mesh, RenderOptions{2});
    for (int v = 0; v < viewCount; ++v) {
      const ViewCentre& view = views[static_cast<std::size_t>(v)];
      const fs::path stem =
          rendersDir / ("head-" + std::to_string(head + 1) + "_" + viewName(view));
      rendered[static_cast<std::size_t>(head * viewCount + v)] =
          renderView(renderer, subject, view, args.size, stem);
      double fraction = 0.0;
      {
        std::lock_guard lock(doneMutex);
        fraction = static_cast<double>(++done) / jobs;
      }
      progress(fraction, {});
    }
  });
  const double renderSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - renderStart).count();

  std::vector<cv::Mat> tiles;
  std::vector<std::string> captions;
  for (int job = 0; job < jobs; ++job) {
    tiles.push_back(rendered[static_cast<std::size_t>(job)].overlay);
    const ViewCentre& view = views[static_cast<std::size_t>(job % viewCount)];
    std::ostringstream caption;
    caption << "head " << job / viewCount + 1 << ": yaw " << view.yawDeg << ", pitch "
            << view.pitchDeg;
    captions.push_back(caption.str());
  }
  writeImage(sheet, makeContactSheet(tiles, 5, captions));

  const int threads = workerCount(static_cast<int>(heads.size()), args.threads);
  std::cout << "demo: " << heads.size() << " heads, " << jobs << " renders at " << args.size << "x"
            << args.size << " in " << std::fixed << std::setprecision(2) << renderSeconds << " s ("
            << std::setprecision(1) << jobs / renderSeconds << " renders/s on " << threads
            << " threads)\n";
  std::cout << "hidden landmarks of head 1 per view (thesis hidden-point removal):\n";
  for (int v = 0; v < viewCount; ++v) {
    const auto& r = rendered[static_cast<std::size_t>(v)];
    std::cout << "  " << std::setw(16) << std::left << viewName(views[static_cast<std::size_t>(v)])
              << std::right << " " << r.hidden << (r.hidden ? ": " + r.hiddenNames : "") << '\n';
  }
}

// The multi-view model trained on the heads (the thesis's chapter 3), saved with its report.
ClmModel trainDemoModel(const DemoArgs& args, const std::vector<SynthHead>& heads,
                        const fs::path& modelPath, const fs::path& reportDir) {
  TrainingInput input;
  input.schemeJson = schemeJsonFor("thesis25");
  input.datasetName = "clm3d demo: procedural heads 1-" + std::to_string(heads.size());
  input.toolVersion = CLM3D_VERSION;
  for (std::size_t i = 0; i < heads.size(); ++i) {
    input.subjects.push_back(
        {"procedural/" + std::to_string(i + 1), &heads[i].mesh, &heads[i].landmarks});
  }
  TrainSettings settings;
  settings.samplesPerView = args.samples;
  settings.threads = args.threads;
  const auto trainStart = std::chrono::steady_clock::now();
  // trainModel reports from its worker threads: DecileProgress keeps its counter under a lock.
  DecileProgress progress = stderrProgress("training");
  ClmModel model = trainModel(input, settings, progress.callback());
  fs::create_directories(modelPath.parent_path());
  saveModel(model, modelPath);
  fs::create_directories(reportDir);
  writeTrainingReport(model, reportDir);
  const double trainSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - trainStart).count();
  std::cout << "demo: trained a " << model.views.size() << "-view, " << settings.scales
            << "-scale model (" << model.shape.modeCount() << " shape modes) in "
            << std::setprecision(1) << trainSeconds << " s: " << modelPath.string() << " ("
            << fs::file_size(modelPath) / 1000000.0 << " MB); report: " << reportDir.string()
            << '\n';
  return model;
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
  settings.textureMaxModes = 16;  // as docs/real-faces.md: 17 MB instead of 139 MB
  settings.threads = args.threads;
  const auto trainStart = std::chrono::steady_clock::now();
  DecileProgress progress = stderrProgress("real-face training");
  const ClmModel model =
      trainFromManifest(args.realManifest, settings, CLM3D_VERSION, progress.callback());
  fs::create_directories(real.model.parent_path());
  saveModel(model, real.model);
  std::cout << "demo: trained the real-face model in " << std::setprecision(1)
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - trainStart).count()
            << " s: " << real.model.string()
            << "\n  LICENCE: it learnt from LFPW photos, which are for research use only (300-W "
               "terms); the model inherits those terms: do not redistribute it or use it "
               "commercially\n";

  TrackerSettings tracking;
  tracking.fit.optimiser = "rlms";
  real.tracks = project_layout::tracksFile(args.out, real.video, real.model);
  fs::create_directories(real.tracks.parent_path());
  TrackTable tracks;
  DecileProgress trackProgress = stderrProgress("franck.mp4");
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
  fs::create_directories(headsDir);
  fs::create_directories(rendersDir);
  const Scheme& scheme = Scheme::thesis25();

  const DemoHeads made = makeHeads(args, headsDir);
  const fs::path sheet = args.out / "training-views.png";
  renderTrainingViews(args, made.heads, rendersDir, sheet);
  const fs::path modelPath = project_layout::modelFile(args.out, kModelName);
  const fs::path reportDir = args.out / "report";
  const ClmModel model = trainDemoModel(args, made.heads, modelPath, reportDir);

  // A held-out head turning frontal -> -60 -> +60 -> frontal (thesis section 5.2).
  std::cerr << "demo: rendering the test sequence of held-out head " << kHeldOutSeed << "\n";
  const SynthHead heldOut = generateHead(kHeldOutSeed, Expression::preset("neutral"));
  SequenceSettings sequence;
  sequence.yawFromDeg = -60.0;
  sequence.yawToDeg = 60.0;
  sequence.order = SequenceOrder::Sweep;
  sequence.stepDeg = args.sequenceStep;
  SequenceSubject subject;
  subject.headSeed = kHeldOutSeed;
  subject.expression = "neutral";
  subject.faceStepDegrees = SynthOptions{}.faceStepDegrees;
  subject.textureSize = SynthOptions{}.textureSize;
  const SequenceFiles files = SequenceFiles::inFolder(args.out / "sequence");
  const SequenceSummary testSequence =
      writeSyntheticSequence(heldOut.mesh, heldOut.landmarks, scheme, sequence, subject, files);
  std::cout << "demo: test sequence of " << testSequence.frames << " frames (" << sequence.width
            << "x" << sequence.height << ", " << sequence.stepDeg
            << " degrees a frame): " << files.video.string() << '\n';

  // Track it from a face detection on the first frame, drawing the overlay as it goes.
  TrackerSettings tracking;
  tracking.fit.optimiser = args.optimiser;
  tracking.fit.scales = 2;
  const fs::path tracksPath = project_layout::tracksFile(args.out, files.video, modelPath);
  fs::create_directories(tracksPath.parent_path());
  const fs::path overlayPath = args.out / "overlay.mp4";
  VideoWriter overlay(overlayPath, sequence.width, sequence.height, sequence.fps);
  TrackTable tracks;
  const TrackSummary tracked =
      trackVideo(files.video, model, tracking, tracks,
                 [&](const cv::Mat& frame, const TrackStep& step, Tracker& tracker) {
                   cv::Mat drawn = frame.clone();
                   drawFitOverlay(drawn, step, tracker.fitter(), scheme);
                   overlay.write(drawn);
                 });
  overlay.close();
  writeTrackTable(tracksPath, tracks);
  std::cout << "demo: tracked " << tracked.frames << " frames with " << args.optimiser << " ("
            << tracked.succeeded << " succeeded, " << tracked.detections
            << " detections); fit time per frame: median " << std::setprecision(2)
            << tracked.medianMilliseconds() << " ms, 90th percentile "
            << tracked.percentileMilliseconds(0.9) << " ms\n";

  // Evaluate against the exact ground truth (thesis eq. 5.1).
  const EvaluationReport report =
      evaluateTrackFiles(files.truth, {tracksPath}, {args.optimiser}, scheme);
  const fs::path evalDir = args.out / "eval";
  fs::create_directories(evalDir);
  writeReportJson(evalDir / "report.json", report);
  writeEvaluationPlots(evalDir, report);

  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "demo: done in " << std::setprecision(1) << total
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
