#include "ui/track/track_jobs.hpp"

#include <algorithm>

#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"
#include "core/model/model_file.hpp"
#include "core/review/review_overlay.hpp"
#include "core/track/keyframe_track.hpp"
#include "core/track/multi_face_tracker.hpp"
#include "core/track/retrack.hpp"
#include "core/track/video_adaptation.hpp"
#include "core/video/video_reader.hpp"
#include "core/video/video_writer.hpp"

namespace clm3d::ui {
namespace {

// Keeps the fit state of each tracked frame, indexed by frame from `first` (a frame the video
// could not give, an unreadable row the tracker hands no image, has none); with first < 0 one per
// call, in the order tracked (the correction loop's spans).
auto recordFits(std::vector<std::optional<FrameFit>>& fits, int first = -1) {
  return [&fits, first](const cv::Mat&, const TrackStep& step, Tracker&) {
    if (first >= 0 && step.row.frame > first) {
      fits.resize(std::max(fits.size(), static_cast<std::size_t>(step.row.frame - first)));
    }
    if (step.fit) {
      fits.push_back(FrameFit{step.fit->state, step.fit->view});
    } else {
      fits.emplace_back();
    }
  };
}

// `model`, or (when null) the model loaded from `path` on the job's thread.
std::shared_ptr<const ClmModel> modelOrLoad(std::shared_ptr<const ClmModel> model,
                                            const std::filesystem::path& path,
                                            const ProgressCallback& progress) {
  if (model) return model;
  progress(0.0, "loading the model");
  return std::make_shared<const ClmModel>(loadModel(path));
}

}  // namespace

JobRunner::Job trackJob(std::filesystem::path video, std::filesystem::path modelPath,
                        std::shared_ptr<const ClmModel> model, TrackerSettings settings,
                        std::shared_ptr<TrackOutcome> outcome) {
  return [video = std::move(video), modelPath = std::move(modelPath), model = std::move(model),
          settings = std::move(settings),
          outcome = std::move(outcome)](const ProgressCallback& progress, CancelToken& cancel) {
    outcome->model = modelOrLoad(model, modelPath, progress);
    cancel.throwIfCancelled();
    if (tracksFaceByFace(settings)) {
      // As `clm3d track --faces`: the rows arrive with their face id in the first extra cell.
      outcome->table.landmarkCount = outcome->model->shape.pointCount();
      outcome->table.extraColumns = {"face"};
      const auto keepFits = [&fits = outcome->faceFits](const cv::Mat&,
                                                        const std::vector<FaceStep>& steps,
                                                        MultiFaceTracker&) {
        for (const FaceStep& face : steps) {
          if (!face.step.fit) continue;
          auto& faceFits = fits[face.face];
          const auto frame = static_cast<std::size_t>(face.step.row.frame);
          if (faceFits.size() <= frame) faceFits.resize(frame + 1);
          faceFits[frame] = FrameFit{face.step.fit->state, face.step.fit->view};
        }
      };
      // Cancelled leaves the rows so far in the outcome, as a single face's track does.
      outcome->summary = trackVideoFaces(
          video, *outcome->model, settings, multiFaceSettings(settings),
          [&table = outcome->table](TrackRow&& row) { table.rows.push_back(std::move(row)); },
          keepFits, progress, &cancel);
    } else {
      outcome->summary = trackVideo(video, *outcome->model, settings, outcome->table,
                                    recordFits(outcome->fits, 0), progress, &cancel);
      outcome->fits.resize(outcome->table.rows.size());  // unreadable frames at the end
    }
    outcome->warning = unreadableFramesWarning(video, outcome->summary);
  };
}

namespace {

// The state that best reproduces `points` (NaN = missing) in `video`'s camera.
FitState stateFromCorrected(const std::filesystem::path& video, const ClmModel& model,
                            const Eigen::Matrix2Xd& points) {
  VideoInfo info;
  {
    const VideoReader probe(video);
    info.width = probe.width();
    info.height = probe.height();
  }
  std::vector<bool> present(static_cast<std::size_t>(points.cols()));
  for (int i = 0; i < points.cols(); ++i) {
    present[static_cast<std::size_t>(i)] = points.col(i).allFinite();
  }
  return stateFromPoints(model, info.camera(), points, present);
}

}  // namespace

JobRunner::Job adaptJob(std::filesystem::path video, std::filesystem::path modelPath,
                        std::shared_ptr<const ClmModel> model, GroundTruthSet truth,
                        std::filesystem::path truthPath, AdaptSettings adapt,
                        TrackerSettings settings, std::filesystem::path out,
                        std::shared_ptr<AdaptOutcome> outcome) {
  return [video = std::move(video), modelPath = std::move(modelPath), model = std::move(model),
          truth = std::move(truth), truthPath = std::move(truthPath), adapt,
          settings = std::move(settings), out = std::move(out),
          outcome = std::move(outcome)](const ProgressCallback& progress, CancelToken& cancel) {
    const std::shared_ptr<const ClmModel> general = modelOrLoad(model, modelPath, progress);
    cancel.throwIfCancelled();
    const auto adapting = [&](double fraction, std::string_view stage) {
      progress(0.6 * fraction, stage);
    };
    auto adapted = std::make_shared<const ClmModel>(adaptToVideo(
        *general, modelPath, video, truth, truthPath, adapt, &outcome->summary, adapting, &cancel));
    cancel.throwIfCancelled();
    const auto tracking = [&](double fraction, std::string_view stage) {
      progress(0.6 + 0.4 * fraction, stage);
    };
    // Through the keyframes, as the correction benchmark measures it: after each corrected frame
    // the adapted model goes on from the corrected points, not from its own track.
    outcome->table.landmarkCount = adapted->shape.pointCount();
    trackThroughKeyframes(
        video, *adapted, settings, truth,
        [&rows = outcome->table.rows](TrackRow&& row) { rows.push_back(std::move(row)); },
        recordFits(outcome->fits, 0), tracking, &cancel);
    outcome->fits.resize(outcome->table.rows.size());
    cancel.throwIfCancelled();
    saveModel(*adapted, out);
    outcome->model = std::move(adapted);
    outcome->saved = out;
  };
}

JobRunner::Job retrackJob(std::filesystem::path video, std::shared_ptr<const ClmModel> model,
                          TrackerSettings settings, int corrected, Eigen::Matrix2Xd points,
                          std::shared_ptr<RetrackOutcome> outcome) {
  return [video = std::move(video), model = std::move(model), settings = std::move(settings),
          corrected, points = std::move(points),
          outcome = std::move(outcome)](const ProgressCallback& progress, CancelToken& cancel) {
    const FitState state = stateFromCorrected(video, *model, points);
    outcome->corrected = corrected;
    retrackFrom(video, *model, settings, corrected, state, -1, outcome->rows,
                recordFits(outcome->fits, corrected + 1), progress, &cancel);
    outcome->fits.resize(outcome->rows.size());  // unreadable frames at the end
  };
}

JobRunner::Job loopRetrackJob(std::filesystem::path video, std::filesystem::path modelPath,
                              std::shared_ptr<const ClmModel> model, TrackerSettings settings,
                              std::vector<int> frames, std::vector<TrackRow> previous,
                              RetrackRules rules, std::shared_ptr<LoopOutcome> outcome) {
  return
      [video = std::move(video), modelPath = std::move(modelPath), model = std::move(model),
       settings = std::move(settings), frames = std::move(frames), previous = std::move(previous),
       rules, outcome = std::move(outcome)](const ProgressCallback& progress, CancelToken& cancel) {
        outcome->model = modelOrLoad(model, modelPath, progress);
        cancel.throwIfCancelled();
        const FitState state = stateFromCorrected(video, *outcome->model, outcome->points);
        retrackSpan(video, *outcome->model, settings, state, -1, frames, previous, rules,
                    outcome->retrack, recordFits(outcome->fits), progress, &cancel);
      };
}

JobRunner::Job exportOverlayJob(std::filesystem::path video, std::filesystem::path out,
                                std::shared_ptr<const ClmModel> model, std::vector<TrackRow> shown,
                                std::vector<std::optional<FrameFit>> fits, bool patches) {
  return [video = std::move(video), out = std::move(out), model = std::move(model),
          shown = std::move(shown), fits = std::move(fits),
          patches](const ProgressCallback& progress, CancelToken& cancel) {
    VideoReader reader(video);
    const Scheme scheme = model->scheme();
    VideoInfo info;
    info.width = reader.width();
    info.height = reader.height();
    Fitter fitter(*model, info.camera(), overlaySearchSettings());
    VideoWriter writer(out, reader.width(), reader.height(), reader.fps());
    FitOverlayOptions options;
    options.patches = patches;
    const int total = reader.frameCount();
    std::vector<std::vector<std::size_t>> rowsOf;  // per frame: its rows in `shown`
    for (std::size_t r = 0; r < shown.size(); ++r) {
      const int f = shown[r].frame;
      if (f < 0) continue;
      if (rowsOf.size() <= static_cast<std::size_t>(f))
        rowsOf.resize(static_cast<std::size_t>(f) + 1);
      rowsOf[static_cast<std::size_t>(f)].push_back(r);
    }
    cv::Mat frame;
    while (reader.read(frame)) {
      cancel.throwIfCancelled();
      const auto index = static_cast<std::size_t>(reader.frameIndex());
      options.label = true;  // once a frame
      for (const std::size_t r :
           index < rowsOf.size() ? rowsOf[index] : std::vector<std::size_t>{}) {
        if (shown[r].points.cols() == 0) continue;
        const std::optional<FrameFit> fit = r < fits.size() ? fits[r] : std::nullopt;
        drawReviewOverlay(frame, shown[r], fit, fitter, scheme, options, true);
        options.label = false;
      }
      writer.write(frame);
      if (total > 0) progress(std::min(1.0, (reader.frameIndex() + 1.0) / total), "exporting");
    }
    writer.close();
  };
}

}  // namespace clm3d::ui
