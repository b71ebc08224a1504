#include "core/track/tracker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"
#include "core/geometry/camera.hpp"
#include "core/refine/refined_fit.hpp"
#include "core/track/detail/unrefined_landmarks.hpp"
#include "core/video/frame_prefetcher.hpp"
#include "core/video/video_reader.hpp"

namespace clm3d {

const char* toString(TrackFailure failure) {
  switch (failure) {
    case TrackFailure::None:
      return "ok";
    case TrackFailure::NoFace:
      return "no face found";
    case TrackFailure::LowConfidence:
      return "low confidence";
    case TrackFailure::ImplausibleShape:
      return "implausible shape";
    case TrackFailure::LeftImage:
      return "face left the image";
  }
  return "unknown";
}

std::vector<Visibility> landmarkVisibility(const ClmModel& model, const Pose& pose) {
  const int n = model.shape.pointCount();
  std::vector<Visibility> visibility(static_cast<std::size_t>(n), Visibility::Unknown);
  const int nearest = model.nearestView(degrees(pose.pitch), degrees(pose.yaw));
  if (nearest < 0 || std::cmp_greater_equal(nearest, model.views.size())) return visibility;
  const ViewModel& view = model.views[static_cast<std::size_t>(nearest)];
  for (int i = 0; i < n && std::cmp_less(i, view.visible.size()); ++i) {
    visibility[static_cast<std::size_t>(i)] =
        view.visible[static_cast<std::size_t>(i)] ? Visibility::Visible : Visibility::Hidden;
  }
  return visibility;
}

double landmarkScoreThreshold(const TrackerSettings& settings, const ClmModel& model) {
  const bool experts =
      makeOptimiser(resolveOptimiser(settings.fit.optimiser, model), settings.fit.optimiserSettings)
          ->usesExperts();
  return builtInScoreAt(experts, settings.minProbability);
}

Tracker::Tracker(const ClmModel& model, const Camera& camera, const TrackerSettings& settings)
    : model_(&model),
      camera_(camera),
      settings_(settings),
      fitter_(model, camera, settings.fit),
      smoother_(settings.smoothing),
      eyes_(model.scheme().normalisationPair()) {
  settings_.fit.optimiser = fitter_.settings().optimiser;  // "auto" resolved for this model
}

Tracker::~Tracker() = default;

void Tracker::reset() {
  lose();
  lastFace_.reset();
}

void Tracker::lose() {
  state_.reset();
  before_.reset();
  view_ = -1;
  smoother_.restart();
}

void Tracker::setState(const FitState& state, int view) {
  state_ = state;
  before_.reset();
  view_ = view;
  lastFace_.reset();
  smoother_.restart();
}

FitState Tracker::nextStart() const {
  FitState start = *state_;
  if (!before_ || settings_.motionPrediction <= 0.0) return start;
  const double k = settings_.motionPrediction;
  const Pose& last = state_->pose;
  const Pose& before = before_->pose;
  start.pose.translation.head<2>() += k * (last.translation - before.translation).head<2>();
  start.pose.scale *= std::pow(last.scale / before.scale, k);
  start.pose.pitch += k * (last.pitch - before.pitch);
  start.pose.yaw += k * (last.yaw - before.yaw);
  start.pose.roll += k * (last.roll - before.roll);
  return start;
}

FaceDetector& Tracker::detector() {
  if (!detector_) detector_ = std::make_unique<FaceDetector>(settings_.detector);
  return *detector_;
}

TrackFailure Tracker::judge(const FitResult& fit) const {
  if (!fit.points.allFinite()) return TrackFailure::LeftImage;
  const Eigen::Vector2d centre = fit.points.rowwise().mean();
  if (centre.x() < 0 || centre.y() < 0 || centre.x() > camera_.width - 1 ||
      centre.y() > camera_.height - 1) {
    return TrackFailure::LeftImage;
  }
  const auto [a, b] = eyes_;
  if ((fit.points.col(a) - fit.points.col(b)).norm() < settings_.minInterOcularPixels &&
      std::abs(fit.state.pose.yaw) < 1.0) {
    return TrackFailure::LeftImage;
  }
  const ShapeModel& shape = model_->shape;
  double mahalanobis = 0.0;
  for (int k = 0; k < shape.modeCount(); ++k) {
    if (shape.variances[k] > 0)
      mahalanobis += fit.state.shape[k] * fit.state.shape[k] / shape.variances[k];
  }
  if (std::sqrt(mahalanobis) > settings_.maxShapeRms * std::sqrt(std::max(1, shape.modeCount()))) {
    return TrackFailure::ImplausibleShape;
  }
  if (!(fit.probability >= settings_.minProbability)) return TrackFailure::LowConfidence;
  return TrackFailure::None;
}

FitState Tracker::carriedState(const FitResult& fit) const {
  if (!fit.refined) return fit.state;  // the search's own points: its own state
  try {
    return stateNearPoints(*model_, camera_, fit.points, fit.modelled, fit.state,
                           nearbyPointsFit());
  } catch (const InputError&) {
    return fit.state;  // too few modelled points to place the model: keep the search's state
  }
}

const cv::Mat& Tracker::greyOf(const cv::Mat& frame) {
  if (frame.type() == CV_8UC3) {
    cv::cvtColor(frame, grey_, cv::COLOR_BGR2GRAY);
    return grey_;
  }
  if (frame.type() == CV_8UC4) {
    cv::cvtColor(frame, grey_, cv::COLOR_BGRA2GRAY);
    return grey_;
  }
  return frame;  // grey already, or a type the fitter refuses with its own message
}

TrackStep Tracker::track(const cv::Mat& input, int index, double timestamp) {
  // Every search, refinement and detection of the frame reads grey levels: the frame is turned
  // grey once here, into a buffer kept between frames, rather than each of them turning the part
  // it cuts out grey (cv::cvtColor works pixel by pixel: the same grey levels).
  const cv::Mat& frame = greyOf(input);
  TrackStep step;
  step.row.frame = index;
  step.row.timestamp = timestamp;
  step.row.points = Eigen::Matrix2Xd::Constant(2, model_->shape.pointCount(),
                                               std::numeric_limits<double>::quiet_NaN());
  double searchMs = 0.0;  // every search of the frame, refinement included
  FitFinisher finish;
  if (settings_.refine && !model_->refiner.empty()) {
    finish = [&](FitResult& fit) {
      const auto begin = std::chrono::steady_clock::now();
      refineFit(*model_, frame, fit);
      step.refineMilliseconds +=
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
              .count();
    };
  }
  // Runs `search` (searches and their refinement), judges its fit and adds its time.
  const auto judged = [&](const auto& search) {
    const auto begin = std::chrono::steady_clock::now();
    try {
      step.fit = search();
      step.failure = judge(*step.fit);
    } catch (const InputError&) {
      // The start put the face outside the image: the track is lost, not the input broken.
      step.fit.reset();
      step.failure = TrackFailure::LeftImage;
    }
    searchMs +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
  };
  // One search from `start`.
  const auto attempt = [&](const FitState& start, int view) {
    judged([&] {
      ++step.searches;
      FitResult fit = fitter_.fit(frame, start, view);
      if (finish) finish(fit);
      return fit;
    });
  };
  // The detected faces, through the face loop every detected image goes through.
  const auto searchFaces = [&](const std::vector<FaceBox>& faces) {
    judged([&] {
      FaceSearch search;
      search.maxFaces = settings_.facesTried;
      search.starts = settings_.startSearch;
      search.accepted = [this](const FitResult& fit) { return judge(fit) == TrackFailure::None; };
      search.finish = finish;
      return fitFromBestFace(fitter_, *model_, frame, faces, search, nullptr, &step.searches);
    });
  };

  const bool fromPrevious = state_.has_value();
  if (fromPrevious) {
    attempt(nextStart(), view_);
    // A prediction that overshoots (the head stopped or turned back) gets a second try from
    // where the face last was, before falling back to the detector.
    if (step.failure != TrackFailure::None && before_) attempt(*state_, view_);
    if (step.fit &&
        wantsViewSearch(*step.fit, settings_.viewSearchBelow, settings_.viewSearchAll)) {
      const auto begin = std::chrono::steady_clock::now();
      const auto passes = [this](const FitResult& fit) { return judge(fit) == TrackFailure::None; };
      step.fit =
          searchNeighbouringViews(fitter_, *model_, frame, *step.fit, settings_.viewSearchMargin,
                                  finish, passes, &step.searches);
      step.failure = judge(*step.fit);
      searchMs +=
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
              .count();
    }
  }
  if (!fromPrevious || step.failure != TrackFailure::None) {
    const auto begin = std::chrono::steady_clock::now();
    std::vector<FaceBox> faces = faceSource_ ? faceSource_(frame) : detector().detect(frame);
    if (lastFace_) faces = preferFacesAt(std::move(faces), *lastFace_);
    step.detectMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
    if (!faces.empty()) {
      step.detected = true;
      // The next face while the fit fails (TrackerSettings::facesTried); without a fit that
      // passes, the most confident stands.
      searchFaces(faces);
    } else if (!fromPrevious) {
      step.failure = TrackFailure::NoFace;
    }
  }
  step.fitMilliseconds = searchMs;
  if (step.failure == TrackFailure::None && step.fit) {
    if (fromPrevious && !step.detected) {
      before_ = state_;
    } else {
      before_.reset();  // a detection is no motion
    }
    state_ = carriedState(*step.fit);
    view_ = step.fit->view;
  } else {
    lose();
  }
  // The row's outline follows the refined points, as a photo's does; the next frame still starts
  // from the state carried above, so tracking is as before.
  if (step.fit) {
    const auto begin = std::chrono::steady_clock::now();
    placeUnrefinedLandmarks(*model_, camera_, *step.fit);
    step.fitMilliseconds +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
    step.row.success = step.failure == TrackFailure::None;
    step.row.confidence = step.fit->probability;
    step.row.view = step.fit->view;
    step.row.pose = step.fit->state.pose;
    step.row.points = step.fit->points;
    step.row.visibility = landmarkVisibility(*model_, step.fit->state.pose);
    step.row.landmarkConfidence = step.fit->landmarkConfidence;
    if (step.row.success) {
      const Eigen::Vector2d centre = step.row.points.rowwise().mean();
      lastFace_ = cv::Point2d(centre.x(), centre.y());
    }
  }
  if (settings_.smoothing.enabled) {
    // A failure is never smoothed over: its points stay as fitted and the filter starts again,
    // as it does on a re-detection (a jump the filter must not drag the points through).
    if (!step.row.success || step.detected) smoother_.restart();
    if (step.row.success) {
      const auto [a, b] = eyes_;
      const double eyes = (step.row.points.col(a) - step.row.points.col(b)).norm();
      smoother_.filter(step.row.points, timestamp, eyes);
    }
  }
  return step;
}

double TrackSummary::percentileMilliseconds(double share) const {
  if (fitMilliseconds.empty()) return 0.0;
  std::vector<double> sorted = fitMilliseconds;
  std::sort(sorted.begin(), sorted.end());
  const double position = std::clamp(share, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
  const auto low = static_cast<std::size_t>(std::floor(position));
  const auto high = std::min(low + 1, sorted.size() - 1);
  return sorted[low] + (position - static_cast<double>(low)) * (sorted[high] - sorted[low]);
}

double TrackSummary::medianMilliseconds() const {
  return percentileMilliseconds(0.5);
}

TrackSummary trackRemainingFrames(VideoReader& reader, Tracker& tracker,
                                  std::vector<TrackRow>& rows, int expectedFrames,
                                  std::string_view stage, const PerFrame& perFrame,
                                  const ProgressCallback& progress, const CancelToken* cancel) {
  return trackRemainingFrames(
      reader, tracker, [&rows](TrackRow&& row) { rows.push_back(std::move(row)); }, expectedFrames,
      stage, perFrame, progress, cancel);
}

int TrackSummary::unreadableFrames() const {
  int count = 0;
  for (const FrameSpan& span : unreadable) count += span.count;
  return count;
}

std::string formatFrameSpans(const std::vector<FrameSpan>& spans, std::size_t shown) {
  std::string text;
  int rest = 0;
  for (std::size_t k = 0; k < spans.size(); ++k) {
    const FrameSpan& span = spans[k];
    if (k >= shown) {
      rest += span.count;
      continue;
    }
    text += (k == 0 ? "" : ", ") + std::to_string(span.first);
    if (span.count > 1) text += "-" + std::to_string(span.first + span.count - 1);
  }
  if (rest > 0) text += " and " + std::to_string(rest) + " more frames";
  return text;
}

std::string unreadableFramesWarning(const std::filesystem::path& video,
                                    const TrackSummary& summary) {
  const int missing = summary.unreadableFrames();
  if (missing == 0) return {};
  std::string what;
  if (summary.declaredFrames > 0) {
    what = "the container declares " + std::to_string(summary.declaredFrames) + " frames but " +
           std::to_string(summary.declaredFrames - missing) + " could be decoded; ";
  }
  what += (missing == 1 ? "frame " : "frames ") + formatFrameSpans(summary.unreadable) +
          (missing == 1 ? " is" : " are") +
          " unreadable (no image: marked unreadable in the tracks)";
  return fileMessage(video, what);
}

namespace {

// The row of a frame the video declares but could not be decoded: nothing tracked.
TrackRow unreadableRow(int frame, double fps, int points) {
  TrackRow row;
  row.frame = frame;
  row.timestamp = frame / fps;
  row.confidence = std::numeric_limits<double>::quiet_NaN();
  row.points = Eigen::Matrix2Xd::Constant(2, points, std::numeric_limits<double>::quiet_NaN());
  row.unreadable = true;
  return row;
}

}  // namespace

TrackSummary trackDecodedFrames(VideoReader& reader, int points, const FrameStep& trackFrame,
                                const TrackRowSink& onRow, int expectedFrames,
                                std::string_view stage, const ProgressCallback& progress,
                                const CancelToken* cancel, int frameLimit) {
  TrackSummary summary;
  summary.declaredFrames = reader.frameCount();
  // The frames this run covers: those declared, up to the limit.
  if (frameLimit >= 0 && summary.declaredFrames > frameLimit) summary.declaredFrames = frameLimit;
  // Progress counts towards the limit too, also when the container does not say how many it holds.
  if (frameLimit >= 0 && (expectedFrames <= 0 || expectedFrames > frameLimit)) {
    expectedFrames = frameLimit;
  }
  const double fps = reader.fps();  // read here: the decoder thread owns the reader below
  const auto skip = [&](int first, int count) {
    summary.unreadable.push_back({first, count});
    for (int f = first; f < first + count; ++f) onRow(unreadableRow(f, fps, points));
  };
  int last = reader.frameIndex();  // the last frame decoded (or before the first one left)
  {
    // Decoded on a thread of its own while the frames before are fitted; destroyed (the thread
    // stopped) before the reader is looked at again, also when Cancelled or a decode error leaves.
    FramePrefetcher frames(reader);
    while (true) {
      if (cancel != nullptr) cancel->throwIfCancelled();
      const DecodedFrame* frame = frames.next();
      if (frame == nullptr) break;
      if (frameLimit >= 0 && frame->index >= frameLimit) {
        // Past the limit: the frames skipped before it that fall short of the limit are missing.
        const int first = frame->index - frame->skippedBefore;
        if (first < frameLimit) skip(first, frameLimit - first);
        last = frameLimit - 1;
        break;
      }
      if (frame->skippedBefore > 0) skip(frame->index - frame->skippedBefore, frame->skippedBefore);
      last = frame->index;
      ++summary.frames;
      trackFrame(frame->image, frame->index, frame->timestamp, summary);
      if (progress && expectedFrames > 0) {
        progress(std::min(1.0, static_cast<double>(summary.frames) / expectedFrames), stage);
      }
    }
  }
  const int tail = summary.declaredFrames - (last + 1);
  if (tail >= kUnreadableTailMinimum) skip(last + 1, tail);
  if (progress) progress(1.0, stage);
  return summary;
}

void countStep(const TrackStep& step, TrackSummary& summary) {
  if (step.row.success) ++summary.succeeded;
  if (step.detected) ++summary.detections;
  if (step.fit) summary.fitMilliseconds.push_back(step.fitMilliseconds);
}

TrackSummary trackRemainingFrames(VideoReader& reader, Tracker& tracker, const TrackRowSink& onRow,
                                  int expectedFrames, std::string_view stage,
                                  const PerFrame& perFrame, const ProgressCallback& progress,
                                  const CancelToken* cancel, int frameLimit) {
  const auto trackFrame = [&](const cv::Mat& image, int index, double timestamp,
                              TrackSummary& summary) {
    TrackStep step = tracker.track(image, index, timestamp);
    countStep(step, summary);
    if (perFrame) perFrame(image, step, tracker);
    onRow(std::move(step.row));
  };
  return trackDecodedFrames(reader, tracker.fitter().model().shape.pointCount(), trackFrame, onRow,
                            expectedFrames, stage, progress, cancel, frameLimit);
}

TrackSummary trackVideo(
    const std::filesystem::path& video, const ClmModel& model, const TrackerSettings& settings,
    TrackTable& table,
    const std::function<void(const cv::Mat&, const TrackStep&, Tracker&)>& perFrame,
    const ProgressCallback& progress, const CancelToken* cancel, std::optional<FitState> initial) {
  table.landmarkCount = model.shape.pointCount();
  return trackVideo(
      video, model, settings, [&table](TrackRow&& row) { table.rows.push_back(std::move(row)); },
      perFrame, progress, cancel, std::move(initial));
}

TrackSummary trackVideo(const std::filesystem::path& video, const ClmModel& model,
                        const TrackerSettings& settings, const TrackRowSink& onRow,
                        const PerFrame& perFrame, const ProgressCallback& progress,
                        const CancelToken* cancel, std::optional<FitState> initial) {
  VideoReader reader(video);
  return trackVideo(reader, model, settings, onRow, perFrame, progress, cancel, std::move(initial));
}

TrackSummary trackVideo(VideoReader& reader, const ClmModel& model, const TrackerSettings& settings,
                        const TrackRowSink& onRow, const PerFrame& perFrame,
                        const ProgressCallback& progress, const CancelToken* cancel,
                        std::optional<FitState> initial, std::unique_ptr<FaceDetector> detector,
                        int frameLimit) {
  const Camera camera =
      Camera::fromVerticalFov(reader.width(), reader.height(), videoFovDeg(settings));
  Tracker tracker(model, camera, settings);
  if (detector) tracker.setDetector(std::move(detector));
  if (initial) tracker.setState(*initial);
  return trackRemainingFrames(reader, tracker, onRow, reader.frameCount(), "tracking", perFrame,
                              progress, cancel, frameLimit);
}

}  // namespace clm3d
