// clm3d demo: runs the whole pipeline on procedural heads, so a new user sees the tool work with
// no data of their own: heads -> renders from the 15 training views with projected,
// visibility-tested landmarks -> a contact sheet -> a 15-view, 3-scale model trained on the heads,
// with its report -> a synthetic test sequence of a held-out head turning through +-60 degrees
// -> tracking it (overlay video with the patches drawn in place) -> the evaluation against the
// exact ground truth, whose summary ends the output. The folder is also a clm3d project (a dataset
// manifest of the heads, the model, the video, its track and ground truth) that clm3d-studio opens.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

#include "app/commands/commands.hpp"
#include "core/common/atomic_file.hpp"
#include "core/eval/eval_plots.hpp"
#include "core/eval/eval_report.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "core/geometry/projection.hpp"
#include "core/mesh/mesh_export.hpp"
#include "core/model/model_file.hpp"
#include "core/project/project.hpp"
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
};

// The held-out head of the test sequence: a seed none of the training heads uses.
constexpr std::uint64_t kHeldOutSeed = 1000;

// The thesis's 15 training views: yaw -60..60 and pitch -30..30 in steps of 30 degrees.
struct View {
  double pitch;
  double yaw;
};
std::vector<View> trainingViews() {
  std::vector<View> views;
  for (double pitch : {-30.0, 0.0, 30.0}) {
    for (double yaw : {-60.0, -30.0, 0.0, 30.0, 60.0}) views.push_back({pitch, yaw});
  }
  return views;
}

struct RenderedView {
  cv::Mat overlay;
  int hidden = 0;
  std::string hiddenNames;
};

RenderedView renderView(OffscreenRenderer& renderer, const SynthHead& head, const View& view,
                        int size, const fs::path& stem) {
  const Scheme& scheme = Scheme::thesis25();
  // Frame the face, not the whole head: the landmarks (earlobes included) span ~85% of the image.
  const Eigen::Matrix3Xd points = head.landmarks.matrix();
  const Eigen::Vector3d centroid = points.rowwise().mean();
  const double radius = (points.colwise() - centroid).colwise().norm().maxCoeff();
  Camera camera = Camera::fromVerticalFov(size, size, 30.0);
  Pose pose = Pose::fromDegrees(view.pitch, view.yaw, 0.0);
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

std::string viewName(const View& view) {
  std::ostringstream name;
  name << "yaw" << std::showpos << static_cast<int>(view.yaw) << "_pitch"
       << static_cast<int>(view.pitch);
  return name.str();
}

struct DemoHeadFile {
  fs::path mesh, landmarks;  // relative to the output folder
  std::string subject, expression;
};

// dataset.json (docs/dataset.md) listing the training heads as scans, so the studio's annotate
// and train pages open them like any scanned dataset. The names are the demo's own (no quoting
// needed).
fs::path writeDemoManifest(const fs::path& out, const std::vector<DemoHeadFile>& heads) {
  std::ostringstream json;
  json << "{\n  \"version\": 1,\n  \"name\": \"clm3d-demo-heads\",\n  \"scheme\": \"thesis25\",\n"
       << "  \"scans\": [\n";
  for (std::size_t i = 0; i < heads.size(); ++i) {
    json << "    {\"mesh\": \"" << heads[i].mesh.generic_string() << "\", \"landmarks\": \""
         << heads[i].landmarks.generic_string() << "\", \"subject\": \"" << heads[i].subject
         << "\", \"expression\": \"" << heads[i].expression << "\"}"
         << (i + 1 < heads.size() ? "," : "") << '\n';
  }
  json << "  ]\n}\n";
  const fs::path path = out / "dataset.json";
  writeTextAtomically(path, json.str());
  return path;
}

void runDemo(const DemoArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const fs::path headsDir = args.out / "heads";
  const fs::path rendersDir = args.out / "renders";
  fs::create_directories(headsDir);
  fs::create_directories(rendersDir);
  const std::vector<std::string> expressions = expressionPresetNames();
  const std::vector<View> views = trainingViews();
  const Scheme& scheme = Scheme::thesis25();

  std::cerr << "demo: generating " << args.heads << " procedural heads\n";
  std::vector<SynthHead> heads;
  std::vector<DemoHeadFile> headFiles;
  for (int i = 0; i < args.heads; ++i) {
    const auto seed = static_cast<std::uint64_t>(i + 1);
    const std::string& expression = expressions[static_cast<std::size_t>(i) % expressions.size()];
    heads.push_back(generateHead(seed, Expression::preset(expression)));
    const fs::path stem = headsDir / ("head-" + std::to_string(seed));
    saveObj(heads.back().mesh, stem.string() + ".obj");
    writeLandmarks(stem.string() + ".ljson", heads.back().landmarks, scheme);
    const std::string name = "head-" + std::to_string(seed);
    headFiles.push_back({fs::path("heads") / (name + ".obj"), fs::path("heads") / (name + ".ljson"),
                         name, expression});
    std::cerr << "  head " << seed << " (" << expression
              << "): " << heads.back().mesh.triangleCount() << " triangles -> " << stem.string()
              << ".obj\n";
  }

  // Render every head from every view, one renderer per worker thread.
  const int jobs = static_cast<int>(heads.size() * views.size());
  const int threads = std::clamp(
      args.threads > 0 ? args.threads : static_cast<int>(std::thread::hardware_concurrency()), 1,
      16);
  std::vector<RenderedView> rendered(static_cast<std::size_t>(jobs));
  std::atomic<int> next{0};
  std::atomic<int> done{0};
  std::mutex errorMutex;
  std::exception_ptr error;
  const auto renderStart = std::chrono::steady_clock::now();
  auto worker = [&] {
    try {
      int current = -1;
      std::unique_ptr<OffscreenRenderer> renderer;
      for (int job = next++; job < jobs; job = next++) {
        const int head = job / static_cast<int>(views.size());
        const View& view = views[static_cast<std::size_t>(job) % views.size()];
        if (head != current) {
          renderer = std::make_unique<OffscreenRenderer>(heads[static_cast<std::size_t>(head)].mesh,
                                                         RenderOptions{2});
          current = head;
        }
        const fs::path stem =
            rendersDir / ("head-" + std::to_string(head + 1) + "_" + viewName(view));
        rendered[static_cast<std::size_t>(job)] =
            renderView(*renderer, heads[static_cast<std::size_t>(head)], view, args.size, stem);
        const int finished = ++done;
        if (finished * 10 / jobs != (finished - 1) * 10 / jobs) {
          std::lock_guard lock(errorMutex);
          std::cerr << "demo: rendered " << finished << "/" << jobs << " views\n";
        }
      }
    } catch (...) {
      std::lock_guard lock(errorMutex);
      if (!error) error = std::current_exception();
      next = jobs;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& thread : pool) thread.join();
  if (error) std::rethrow_exception(error);
  const double renderSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - renderStart).count();

  std::vector<cv::Mat> tiles;
  std::vector<std::string> captions;
  for (int job = 0; job < jobs; ++job) {
    tiles.push_back(rendered[static_cast<std::size_t>(job)].overlay);
    const View& view = views[static_cast<std::size_t>(job) % views.size()];
    std::ostringstream caption;
    caption << "head " << job / static_cast<int>(views.size()) + 1 << ": yaw " << view.yaw
            << ", pitch " << view.pitch;
    captions.push_back(caption.str());
  }
  const fs::path sheet = args.out / "training-views.png";
  writeImage(sheet, makeContactSheet(tiles, static_cast<int>(5), captions));

  std::cout << "demo: " << heads.size() << " heads, " << jobs << " renders at " << args.size << "x"
            << args.size << " in " << std::fixed << std::setprecision(2) << renderSeconds << " s ("
            << std::setprecision(1) << jobs / renderSeconds << " renders/s on " << threads
            << " threads)\n";
  std::cout << "hidden landmarks of head 1 per view (thesis hidden-point removal):\n";
  for (std::size_t v = 0; v < views.size(); ++v) {
    const auto& r = rendered[v];
    std::cout << "  " << std::setw(16) << std::left << viewName(views[v]) << std::right << " "
              << r.hidden << (r.hidden ? ": " + r.hiddenNames : "") << '\n';
  }
  // Train the multi-view model on the same heads (the thesis's chapter 3).
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
  settings.threads = threads;
  const auto trainStart = std::chrono::steady_clock::now();
  int lastDecile = -1;
  const ClmModel model = trainModel(input, settings, [&](double fraction, std::string_view stage) {
    const int decile = static_cast<int>(fraction * 10.0);
    if (decile == lastDecile) return;
    lastDecile = decile;
    std::cerr << "demo: training " << stage << " " << decile * 10 << "%\n";
  });
  const fs::path modelPath = args.out / "model.clm3d";
  saveModel(model, modelPath);
  const fs::path reportDir = args.out / "report";
  fs::create_directories(reportDir);
  writeTrainingReport(model, reportDir);
  const double trainSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - trainStart).count();
  std::cout << "demo: trained a " << model.views.size() << "-view, " << settings.scales
            << "-scale model (" << model.shape.modeCount() << " shape modes) in "
            << std::setprecision(1) << trainSeconds << " s: " << modelPath.string() << " ("
            << fs::file_size(modelPath) / 1000000.0 << " MB); report: " << reportDir.string()
            << '\n';

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
  const fs::path tracksPath = args.out / "tracks.csv";
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
  project.manifest = fs::absolute(writeDemoManifest(args.out, headFiles));
  project.models = {fs::absolute(modelPath)};
  project.videos = {fs::absolute(files.video)};
  project.tracks = {fs::absolute(tracksPath)};
  project.groundTruth = {fs::absolute(files.truth)};
  saveProject(project);

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
  command->callback([args] { runDemo(*args); });
}

}  // namespace clm3d::cli
