#include "core/demo/detail/demo_pipeline.hpp"

#include <iomanip>
#include <sstream>

#include "core/common/job_progress.hpp"
#include "core/common/parallel_for.hpp"
#include "core/demo/detail/procedural_heads.hpp"
#include "core/geometry/projection.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/render/projected_landmarks.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/fit_overlay.hpp"
#include "core/train/trainer.hpp"
#include "core/video/video_writer.hpp"
#include "core/viz/contact_sheet.hpp"
#include "core/viz/image_file.hpp"
#include "core/viz/landmark_overlay.hpp"

namespace clm3d {

namespace fs = std::filesystem;

namespace {

// One head from one view, framed on the face (not the whole head: the landmarks, earlobes
// included, span ~85% of the image); the render and its projected points written beside `stem`.
DemoRender renderView(OffscreenRenderer& renderer, const SynthHead& head, const ViewCentre& view,
                      int size, const fs::path& stem) {
  const Scheme& scheme = Scheme::thesis25();
  const Eigen::Matrix3Xd points = head.landmarks.matrix();
  const Eigen::Vector3d centroid = points.rowwise().mean();
  const double radius = (points.colwise() - centroid).colwise().norm().maxCoeff();
  Camera camera = Camera::fromVerticalFov(size, size, 30.0);
  Pose pose = Pose::fromDegrees(view.pitchDeg, view.yawDeg, 0.0);
  pose.translation = -(pose.rotation() * centroid);
  pose.translation.z() += distanceToFit(radius, camera, 0.85);
  camera = Camera::fromVerticalFov(size, size, 30.0, 10.0, -pose.translation.z() + 400.0);
  const RenderResult result = renderer.render(pose, camera);

  const ProjectedLandmarks projected = projectLandmarks(head.landmarks, result, pose, camera);
  writeImage(stem.string() + ".png", result.bgra);
  writeLandmarks(stem.string() + ".pts", projected.points, scheme);
  DemoRender rendered;
  rendered.overlay = result.bgra.clone();
  drawLandmarks(rendered.overlay, projected.points, projected.visible, scheme, {false, 1.0});
  rendered.hidden = projected.hidden;
  return rendered;
}

}  // namespace

DemoHeads writeDemoHeads(int count, const fs::path& headsDir, const SynthOptions& options,
                         const std::function<void(const WrittenHead&, const SynthHead&)>& onHead) {
  DemoHeads made;
  made.manifest.name = "clm3d-demo-heads";
  writeProceduralHeads(
      1, count, expressionPresetNames(), options, headsDir,
      [&made, &onHead](const WrittenHead& written, SynthHead&& head) {
        made.heads.push_back(std::move(head));
        made.meshFiles.push_back(written.mesh);
        made.manifest.scans.push_back({fs::absolute(written.mesh), fs::absolute(written.landmarks),
                                       written.mesh.stem().string(), written.expression});
        if (onHead) onHead(written, made.heads.back());
      });
  return made;
}

std::string demoViewName(const ViewCentre& view) {
  std::ostringstream name;
  name << "yaw" << std::showpos << static_cast<int>(view.yawDeg) << "_pitch"
       << static_cast<int>(view.pitchDeg);
  return name.str();
}

DemoRenders renderDemoViews(const std::vector<SynthHead>& heads, int size, int threads,
                            const fs::path& rendersDir, const ProgressCallback& progress) {
  DemoRenders made;
  made.views = TrainSettings{}.views();
  const int viewCount = static_cast<int>(made.views.size());
  const int headCount = static_cast<int>(heads.size());
  const int jobs = headCount * viewCount;
  made.renders.resize(static_cast<std::size_t>(jobs));
  made.threads = workerCount(headCount, threads);
  fs::create_directories(rendersDir);
  JobProgress done(progress, jobs, {});
  parallelFor(headCount, threads, [&](int head) {
    const SynthHead& subject = heads[static_cast<std::size_t>(head)];
    OffscreenRenderer renderer(subject.mesh, RenderOptions{2});
    for (int v = 0; v < viewCount; ++v) {
      const ViewCentre& view = made.views[static_cast<std::size_t>(v)];
      const fs::path stem =
          rendersDir / ("head-" + std::to_string(head + 1) + "_" + demoViewName(view));
      made.renders[static_cast<std::size_t>(head * viewCount + v)] =
          renderView(renderer, subject, view, size, stem);
      done.finished();
    }
  });
  return made;
}

cv::Mat demoContactSheet(const DemoRenders& renders) {
  const std::size_t viewCount = renders.views.size();
  std::vector<cv::Mat> tiles;
  std::vector<std::string> captions;
  for (std::size_t job = 0; job < renders.renders.size(); ++job) {
    tiles.push_back(renders.renders[job].overlay);
    const ViewCentre& view = renders.views[job % viewCount];
    std::ostringstream caption;
    caption << "head " << job / viewCount + 1 << ": yaw " << view.yawDeg << ", pitch "
            << view.pitchDeg;
    captions.push_back(caption.str());
  }
  return makeContactSheet(tiles, 5, captions);
}

std::string formatHiddenLandmarks(const DemoRenders& renders, int head) {
  const Scheme& scheme = Scheme::thesis25();
  const std::size_t viewCount = renders.views.size();
  std::ostringstream text;
  for (std::size_t v = 0; v < viewCount; ++v) {
    const DemoRender& render = renders.renders.at(static_cast<std::size_t>(head) * viewCount + v);
    std::string names;
    for (const int i : render.hidden) names += (names.empty() ? "" : ", ") + scheme.id(i);
    text << "  " << std::setw(16) << std::left << demoViewName(renders.views[v]) << std::right
         << " " << render.hidden.size() << (render.hidden.empty() ? "" : ": " + names) << '\n';
  }
  return text.str();
}

TrainSettings demoTrainSettings(int samplesPerView, int threads) {
  TrainSettings settings;
  settings.samplesPerView = samplesPerView;
  settings.threads = threads;
  // Every texture mode the variance keeps: the demo tracks with the thesis's templates (fastncc),
  // which synthesise from the texture modes, and its model of procedural heads stays small (the
  // cap of `clm3d train`, 16 by default, is for models trained with photos). Capped at 16, the
  // demo's sequence tracked 15 of its frames instead of 16, mean error 0.106 instead of < 0.1.
  settings.textureMaxModes = 0;
  return settings;
}

ClmModel trainDemoModel(const std::vector<SynthHead>& heads, const TrainSettings& settings,
                        const std::string& toolVersion, const ProgressCallback& progress) {
  TrainingInput input;
  input.schemeJson = schemeJsonFor("thesis25");
  input.datasetName = "clm3d demo: procedural heads 1-" + std::to_string(heads.size());
  input.toolVersion = toolVersion;
  for (std::size_t i = 0; i < heads.size(); ++i) {
    input.subjects.push_back(
        {"procedural/" + std::to_string(i + 1), &heads[i].mesh, &heads[i].landmarks});
  }
  return trainModel(input, settings, progress);
}

DemoSequence writeDemoSequence(double stepDeg, const fs::path& folder) {
  const SynthHead heldOut = generateHead(kDemoHeldOutSeed, Expression::preset("neutral"));
  DemoSequence sequence;
  sequence.settings.yawFromDeg = -60.0;
  sequence.settings.yawToDeg = 60.0;
  sequence.settings.order = SequenceOrder::Sweep;
  sequence.settings.stepDeg = stepDeg;
  SequenceSubject subject;
  subject.headSeed = kDemoHeldOutSeed;
  subject.expression = "neutral";
  subject.faceStepDegrees = SynthOptions{}.faceStepDegrees;
  subject.textureSize = SynthOptions{}.textureSize;
  sequence.files = SequenceFiles::inFolder(folder);
  sequence.summary = writeSyntheticSequence(heldOut.mesh, heldOut.landmarks, Scheme::thesis25(),
                                            sequence.settings, subject, sequence.files);
  return sequence;
}

TrackerSettings demoTrackerSettings(const std::string& optimiser) {
  TrackerSettings tracking;
  tracking.fit.optimiser = optimiser;
  tracking.fit.scales = 2;
  return tracking;
}

TrackSummary trackWithOverlay(const fs::path& video, const ClmModel& model,
                              const TrackerSettings& settings, TrackTable& tracks,
                              const fs::path& overlay, int width, int height, double fps) {
  const Scheme scheme = model.scheme();
  VideoWriter writer(overlay, width, height, fps);
  const TrackSummary tracked =
      trackVideo(video, model, settings, tracks,
                 [&](const cv::Mat& frame, const TrackStep& step, Tracker& tracker) {
                   cv::Mat drawn = frame.clone();
                   drawFitOverlay(drawn, frame, step, tracker.fitter(), scheme);
                   writer.write(drawn);
                 });
  writer.close();
  return tracked;
}

}  // namespace clm3d
