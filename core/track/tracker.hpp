// Tracking (thesis section 4.3): each frame is searched from the previous frame's result; a frame
// whose fit looks wrong (low confidence, implausible shape, face leaving the image) is marked as
// failed and the face is detected again, in the same frame and from then on until a fit succeeds.
// Safe on a worker thread: trackVideo reports progress and stops on its cancel token.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "core/common/progress.hpp"
#include "core/detect/face_detector.hpp"
#include "core/fit/fitter.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

class VideoReader;

struct TrackerSettings {
  FitSettings fit;
  DetectorKind detector = DetectorKind::Cascade;
  double minConfidence = 0.35;  // mean NCC below this marks the frame as failed
  // Root mean square of b_k / SD_k beyond which the shape is implausible: a real face sits near 1;
  // with every mode clamped to +-3 SD, 2.5 means most modes are pressed against their limits.
  double maxShapeRms = 2.5;
  double minInterOcularPixels = 8.0;  // a smaller face is a lost track
  // Each frame starts from the previous pose moved on by this share of the last frame-to-frame
  // pose change (constant-velocity prediction; the shape is not extrapolated), so a turning head
  // does not leave the search a growing lag to make up. 0 starts from the previous pose.
  double motionPrediction = 1.0;
  // A frame tracked with a mean NCC below this is searched again from the neighbouring views in
  // yaw (half-way to their centres), and the better result kept if its NCC is higher by the
  // margin: a head turning past a view's range is caught by the next view before it is lost.
  // 0 switches the search off.
  double viewSearchConfidence = 0.7;
  double viewSearchMargin = 0.02;
};

// Per landmark, whether it is visible from `pose`: whether the model view whose centre is nearest
// the pose's (pitch, yaw) holds it (ViewModel::visible: the landmark passed the depth test in at
// least half of that view's training renders). The nearest view, not the fit's selected one (which
// lags by the selector's hysteresis), so the answer depends on the fitted pose alone. n entries.
std::vector<Visibility> landmarkVisibility(const ClmModel& model, const Pose& pose);

// Why a frame failed (or None).
enum class TrackFailure { None, NoFace, LowConfidence, ImplausibleShape, LeftImage };
const char* toString(TrackFailure failure);

struct TrackStep {
  TrackRow row;
  std::optional<FitResult> fit;  // absent when no face was found
  TrackFailure failure = TrackFailure::None;
  bool detected = false;         // this frame started from a detection
  double fitMilliseconds = 0.0;  // all searches of the frame (no detection, no decoding)
};

class Tracker {
 public:
  Tracker(const ClmModel& model, const Camera& camera, const TrackerSettings& settings = {});
  ~Tracker();

  // Tracks one frame (BGR or grey, the camera's size).
  TrackStep track(const cv::Mat& frame, int index, double timestamp);
  // Forget the previous frame: the next frame starts from a detection.
  void reset();
  // Start the next frame from this state (a hand-corrected frame, or --init points).
  void setState(const FitState& state, int view = -1);
  // Where the next frame's search starts: the last state, its pose moved on by the motion
  // prediction once two consecutive frames were tracked. Only valid while tracking (not lost).
  FitState nextStart() const;

  Fitter& fitter() { return fitter_; }
  const TrackerSettings& settings() const { return settings_; }

 private:
  TrackFailure judge(const FitResult& fit) const;
  template <typename Attempt>
  void searchNeighbouringViews(TrackStep& step, Attempt& attempt);
  FaceDetector& detector();

  const ClmModel* model_;
  Camera camera_;
  TrackerSettings settings_;
  Fitter fitter_;
  std::unique_ptr<FaceDetector> detector_;
  std::optional<FitState> state_;
  std::optional<FitState> before_;  // the successful frame before state_'s, for the prediction
  int view_ = -1;
};

struct TrackSummary {
  int frames = 0;
  int succeeded = 0;
  int detections = 0;
  std::vector<double> fitMilliseconds;  // per fitted frame
  double medianMilliseconds() const;
  double percentileMilliseconds(double share) const;
};

// Tracks every frame `reader` has left with `tracker`, appending the rows to `rows`: the loop
// trackVideo and retrackFrom share. Progress `stage` goes 0..1 over `expectedFrames` (0 = unknown);
// Cancelled when cancelled, the rows so far kept.
using PerFrame = std::function<void(const cv::Mat&, const TrackStep&, Tracker&)>;
TrackSummary trackRemainingFrames(VideoReader& reader, Tracker& tracker,
                                  std::vector<TrackRow>& rows, int expectedFrames,
                                  std::string_view stage, const PerFrame& perFrame,
                                  const ProgressCallback& progress, const CancelToken* cancel);

// Tracks every frame of a video into `table` (rows in frame order). perFrame (optional) sees each
// frame with its step, e.g. to draw the overlay. Progress stage "tracking". Throws InputError for
// an unreadable video, Cancelled when cancelled (the rows so far stay in `table`).
TrackSummary trackVideo(
    const std::filesystem::path& video, const ClmModel& model, const TrackerSettings& settings,
    TrackTable& table,
    const std::function<void(const cv::Mat&, const TrackStep&, Tracker&)>& perFrame = {},
    const ProgressCallback& progress = {}, const CancelToken* cancel = nullptr,
    std::optional<FitState> initial = std::nullopt);

}  // namespace clm3d
