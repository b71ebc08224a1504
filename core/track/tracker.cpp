#include "core/track/tracker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"
#include "core/geometry/camera.hpp"
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

Tracker::Tracker(const ClmModel& model, const Camera& camera, const TrackerSettings& settings)
    : model_(&model), camera_(camera), settings_(settings), fitter_(model, camera, settings.fit) {}

Tracker::~Tracker() = default;

void Tracker::reset() {
  state_.reset();
  view_ = -1;
}

void Tracker::setState(const FitState& state, int view) {
  state_ = state;
  view_ = view;
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
  const auto [a, b] = model_->scheme().normalisationPair();
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
  if (fit.confidence < settings_.minConfidence) return TrackFailure::LowConfidence;
  return TrackFailure::None;
}

TrackStep Tracker::track(const cv::Mat& frame, int index, double timestamp) {
  TrackStep step;
  step.row.frame = index;
  step.row.timestamp = timestamp;
  step.row.points = Eigen::Matrix2Xd::Constant(2, model_->shape.pointCount(),
                                               std::numeric_limits<double>::quiet_NaN());
  const auto attempt = [&](const FitState& start, int view) {
    const auto begin = std::chrono::steady_clock::now();
    try {
      step.fit = fitter_.fit(frame, start, view);
      step.failure = judge(*step.fit);
    } catch (const InputError&) {
      // The start put the face outside the image: the track is lost, not the input broken.
      step.fit.reset();
      step.failure = TrackFailure::LeftImage;
    }
    step.fitMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
  };

  const bool fromPrevious = state_.has_value();
  if (fromPrevious) attempt(*state_, view_);
  if (!fromPrevious || step.failure != TrackFailure::None) {
    const std::vector<FaceBox> faces = detector().detect(frame);
    if (!faces.empty()) {
      step.detected = true;
      attempt(stateFromBox(*model_, camera_, faces.front()), -1);
    } else if (!fromPrevious) {
      step.failure = TrackFailure::NoFace;
    }
  }

  if (step.failure == TrackFailure::None && step.fit) {
    state_ = step.fit->state;
    view_ = step.fit->view;
  } else {
    reset();
  }
  if (step.fit) {
    step.row.success = step.failure == TrackFailure::None;
    step.row.confidence = step.fit->confidence;
    step.row.view = step.fit->view;
    step.row.pose = step.fit->state.pose;
    step.row.points = step.fit->points;
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

TrackSummary trackVideo(
    const std::filesystem::path& video, const ClmModel& model, const TrackerSettings& settings,
    TrackTable& table,
    const std::function<void(const cv::Mat&, const TrackStep&, Tracker&)>& perFrame,
    const ProgressCallback& progress, const CancelToken* cancel, std::optional<FitState> initial) {
  VideoReader reader(video);
  const Camera camera =
      Camera::fromVerticalFov(reader.width(), reader.height(), kDefaultVerticalFovDeg);
  Tracker tracker(model, camera, settings);
  if (initial) tracker.setState(*initial);
  table.landmarkCount = model.shape.pointCount();
  TrackSummary summary;
  const int total = reader.frameCount();
  cv::Mat frame;
  while (true) {
    if (cancel != nullptr) cancel->throwIfCancelled();
    if (!reader.read(frame)) break;
    TrackStep step = tracker.track(frame, reader.frameIndex(), reader.timestamp());
    ++summary.frames;
    if (step.row.success) ++summary.succeeded;
    if (step.detected) ++summary.detections;
    if (step.fit) summary.fitMilliseconds.push_back(step.fitMilliseconds);
    if (perFrame) perFrame(frame, step, tracker);
    table.rows.push_back(std::move(step.row));
    if (progress && total > 0) {
      progress(std::min(1.0, static_cast<double>(summary.frames) / total), "tracking");
    }
  }
  if (progress) progress(1.0, "tracking");
  return summary;
}

}  // namespace clm3d
