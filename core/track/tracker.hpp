// Tracking (thesis section 4.3): each frame is searched from the previous frame's result; a frame
// whose fit looks wrong (low confidence, implausible shape, face leaving the image) is marked as
// failed and the face is detected again, in the same frame and from then on until a fit succeeds.
// Safe on a worker thread: trackVideo reports progress and stops on its cancel token.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/common/progress.hpp"
#include "core/detect/face_detector.hpp"
#include "core/detect/start_search.hpp"
#include "core/fit/fitter.hpp"
#include "core/refine/descent_refinement.hpp"
#include "core/track/face_search_settings.hpp"
#include "core/track/track_smoother.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

class VideoReader;

// The tracker's settings: how a face is found and fitted in one image (FaceSearchSettings, shared
// with a still image's fit; the tracker reads the fields that struct names as read by both) and
// the tracker's own: failure thresholds, motion, view search, smoothing, faces.
struct TrackerSettings : FaceSearchSettings {
  // Root mean square of b_k / SD_k beyond which the shape is implausible: a real face sits near 1;
  // with every mode clamped to +-3 SD, 2.5 means most modes are pressed against their limits.
  double maxShapeRms = 2.5;
  double minInterOcularPixels = 8.0;  // a smaller face is a lost track
  // Each frame starts from the previous pose moved on by this share of the last frame-to-frame
  // pose change (constant-velocity prediction; the shape is not extrapolated), so a turning head
  // does not leave the search a growing lag to make up. 0 starts from the previous pose.
  double motionPrediction = 1.0;
  // Temporal smoothing of the written points (off by default). Only the rows' points are
  // smoothed: every frame is still searched from the raw fit, the pose, confidences and success
  // are the fit's, and a failed or re-detected frame restarts the filter with its points as fitted.
  SmoothingSettings smoothing;
  // Faces tracked at once (`clm3d track --faces`, the studio's "Faces to track"): 1 = one face
  // (trackVideo, a tracks table without a face column), N = at most N, 0 = every face
  // (trackVideoFaces, core/track/multi_face_tracker.hpp). A Tracker follows one face and does not
  // read it.
  int faces = 1;

  bool operator==(const TrackerSettings&) const = default;
};

// Per landmark, whether it is visible from `pose`: whether the model view whose centre is nearest
// the pose's (pitch, yaw) holds it (ViewModel::visible: the landmark passed the depth test in at
// least half of that view's training renders). The nearest view, not the fit's selected one (which
// lags by the selector's hysteresis), so the answer depends on the fitted pose alone. n entries.
std::vector<Visibility> landmarkVisibility(const ClmModel& model, const Pose& pose);

// The score (FitResult::landmarkConfidence, on the scale of `settings`' optimiser resolved for
// `model`) below which the studio marks a landmark as doubtful: where the built-in curve of that
// optimiser's scores (core/fit/fit_probability.hpp) reaches settings.minProbability.
double landmarkScoreThreshold(const TrackerSettings& settings, const ClmModel& model);

// Why a frame failed (or None).
enum class TrackFailure { None, NoFace, LowConfidence, ImplausibleShape, LeftImage };
const char* toString(TrackFailure failure);

struct TrackStep {
  TrackRow row;
  std::optional<FitResult> fit;  // absent when no face was found
  TrackFailure failure = TrackFailure::None;
  bool detected = false;            // this frame started from a detection
  double fitMilliseconds = 0.0;     // all searches of the frame (no detection, no decoding)
  double refineMilliseconds = 0.0;  // of fitMilliseconds: the point refinement and its check
  double detectMilliseconds = 0.0;  // the face detection (not in fitMilliseconds)
  int searches = 0;                 // Fitter::fit runs (a detection's start grid counts as one)
};

class Tracker {
 public:
  Tracker(const ClmModel& model, const Camera& camera, const TrackerSettings& settings = {});
  ~Tracker();

  // Tracks one frame (BGR or grey, the camera's size).
  TrackStep track(const cv::Mat& frame, int index, double timestamp);
  // Forget the previous frames: the next frame starts from a detection of any face.
  void reset();
  // Start the next frame from this state (a hand-corrected frame, or --init points). Both restart
  // the smoother.
  void setState(const FitState& state, int view = -1);
  // Where the next frame's search starts: the last state, its pose moved on by the motion
  // prediction once two consecutive frames were tracked. Only valid while tracking (not lost).
  FitState nextStart() const;
  // Whether the next frame continues from a state (false: it starts from a detection).
  bool tracking() const { return state_.has_value(); }
  // The centre of the last tracked frame's points (kept while the track is lost), if any.
  const std::optional<cv::Point2d>& lastFace() const { return lastFace_; }

  // Where a frame that needs a detection gets its faces, best first. Unset: the tracker's own
  // detector over the whole frame. MultiFaceTracker sets it to hand each face's tracker only the
  // faces no other face's tracker holds. The source must outlive the tracker's use of it.
  using FaceSource = std::function<std::vector<FaceBox>(const cv::Mat& frame)>;
  void setFaceSource(FaceSource source) { faceSource_ = std::move(source); }
  // The detector a frame that needs a detection (and has no face source) uses. Unset: one of
  // settings.detector built when first needed. clm3d track builds it beside the model's loading.
  void setDetector(std::unique_ptr<FaceDetector> detector) { detector_ = std::move(detector); }

  Fitter& fitter() { return fitter_; }
  const TrackerSettings& settings() const { return settings_; }

 private:
  TrackFailure judge(const FitResult& fit) const;
  // The state a passing frame hands to the next: for a refined fit, the state nearest the
  // search's that reproduces the refined points (stateNearPoints), so that the
  // next search starts where the output points are, not where the search's own 3D state drifted;
  // otherwise the search's state.
  FitState carriedState(const FitResult& fit) const;
  FaceDetector& detector();
  // The frame in grey (8-bit BGR and BGRA converted into grey_; any other type as it is).
  const cv::Mat& greyOf(const cv::Mat& frame);
  void lose();  // the next frame starts from a detection (preferring the face last tracked)

  const ClmModel* model_;
  Camera camera_;
  TrackerSettings settings_;
  Fitter fitter_;
  std::unique_ptr<FaceDetector> detector_;
  FaceSource faceSource_;
  std::optional<FitState> state_;
  std::optional<FitState> before_;  // the successful frame before state_'s, for the prediction
  int view_ = -1;
  // The centre of the last tracked frame's points, kept while the track is lost (not by reset or
  // setState): a detection prefers the face there (preferFacesAt).
  std::optional<cv::Point2d> lastFace_;
  PointSmoother smoother_;
  std::pair<int, int> eyes_;  // the scheme's normalisation pair (parsed once)
  cv::Mat grey_;              // the frame being tracked, in grey (greyOf)
};

struct TrackSummary {
  int frames = 0;  // frames decoded and tracked
  int succeeded = 0;
  int detections = 0;
  std::vector<double> fitMilliseconds;  // per fitted frame
  double medianMilliseconds() const;
  double percentileMilliseconds(double share) const;
  // Frames the video declares but that could not be decoded, in frame order: gaps in the middle
  // (VideoReader::skippedBefore) and, when at least kUnreadableTailMinimum frames are missing
  // there, the declared frames after the last decoded one (a truncated file). Each has a row
  // marked unreadable (TrackRow::unreadable); nothing else about the other frames changes.
  std::vector<FrameSpan> unreadable;
  int declaredFrames = -1;  // VideoReader::frameCount(): -1 when the container states none
  int unreadableFrames() const;
};

// A shortfall of one frame at the end is not reported: containers without a frame count
// (Matroska, WebM, raw streams) give one estimated from the duration, which can be one off.
inline constexpr int kUnreadableTailMinimum = 2;

// "FILE: the container declares N frames but M could be decoded; frames A-B, C are unreadable
// (no image: marked unreadable in the tracks)"; empty when the summary has no unreadable frame.
// What `clm3d track`, `clm3d batch` and the studio warn with.
std::string unreadableFramesWarning(const std::filesystem::path& video,
                                    const TrackSummary& summary);
// "A-B, C, ..." (at most `shown` spans, then "and N more frames").
std::string formatFrameSpans(const std::vector<FrameSpan>& spans, std::size_t shown = 8);

// Tracks every frame `reader` has left with `tracker`, appending the rows to `rows`: the loop
// trackVideo and retrackFrom share. The frames are decoded on a thread of their own a few frames
// ahead of the fit (core/video/frame_prefetcher), in order; a decode error is thrown here. Frames
// the video declares but could not be decoded get unreadable rows (TrackSummary::unreadable), in
// frame order among the others; perFrame does not see them. Progress `stage` goes 0..1 over
// `expectedFrames` (0 = unknown); Cancelled when cancelled, the rows so far kept.
using PerFrame = std::function<void(const cv::Mat&, const TrackStep&, Tracker&)>;
TrackSummary trackRemainingFrames(VideoReader& reader, Tracker& tracker,
                                  std::vector<TrackRow>& rows, int expectedFrames,
                                  std::string_view stage, const PerFrame& perFrame,
                                  const ProgressCallback& progress, const CancelToken* cancel);
// The same, handing each row to `onRow` as it is made instead of keeping it.
using TrackRowSink = std::function<void(TrackRow&&)>;
// With frameLimit >= 0 it stops before frame frameLimit (trackDecodedFrames).
TrackSummary trackRemainingFrames(VideoReader& reader, Tracker& tracker, const TrackRowSink& onRow,
                                  int expectedFrames, std::string_view stage,
                                  const PerFrame& perFrame, const ProgressCallback& progress,
                                  const CancelToken* cancel, int frameLimit = -1);

// The loop under trackRemainingFrames and trackVideoFaces (core/track/multi_face_tracker.hpp):
// decodes the reader's remaining frames on a thread of their own, hands each to `trackFrame` in
// frame order (it tracks the frame, gives its rows to `onRow` and counts them in the summary;
// TrackSummary::frames is already counted), writes an unreadable row (`points` NaN columns) for
// each frame the video declares but could not be decoded, reports progress and stops on `cancel`.
// With frameLimit >= 0 it stops before frame frameLimit: the summary's declaredFrames and the
// frames progress expects are then at most the limit, and frames beyond it are neither decoded
// nor missing.
using FrameStep =
    std::function<void(const cv::Mat& image, int index, double timestamp, TrackSummary& summary)>;
TrackSummary trackDecodedFrames(VideoReader& reader, int points, const FrameStep& trackFrame,
                                const TrackRowSink& onRow, int expectedFrames,
                                std::string_view stage, const ProgressCallback& progress,
                                const CancelToken* cancel, int frameLimit = -1);
// Counts a tracked step in the summary: success, detection and fit time.
void countStep(const TrackStep& step, TrackSummary& summary);

// Tracks every frame of a video into `table` (rows in frame order). perFrame (optional) sees each
// frame with its step, e.g. to draw the overlay. Progress stage "tracking". Throws InputError for
// an unreadable video, Cancelled when cancelled (the rows so far stay in `table`).
TrackSummary trackVideo(
    const std::filesystem::path& video, const ClmModel& model, const TrackerSettings& settings,
    TrackTable& table,
    const std::function<void(const cv::Mat&, const TrackStep&, Tracker&)>& perFrame = {},
    const ProgressCallback& progress = {}, const CancelToken* cancel = nullptr,
    std::optional<FitState> initial = std::nullopt);
// The same, handing each row (frame order; the model's point count) to `onRow` as it is made, so
// that nothing grows with the video's length (a TrackTableWriter streams them to a file).
TrackSummary trackVideo(const std::filesystem::path& video, const ClmModel& model,
                        const TrackerSettings& settings, const TrackRowSink& onRow,
                        const PerFrame& perFrame = {}, const ProgressCallback& progress = {},
                        const CancelToken* cancel = nullptr,
                        std::optional<FitState> initial = std::nullopt);
// The same from a reader opened by the caller (the frames it has left: all of a fresh one), with
// the tracker's detector when given (Tracker::setDetector), so that a caller that opened the video
// to look at it first does not open it again; with frameLimit >= 0 only the frames before
// frameLimit (`clm3d track --last`).
TrackSummary trackVideo(VideoReader& reader, const ClmModel& model, const TrackerSettings& settings,
                        const TrackRowSink& onRow, const PerFrame& perFrame,
                        const ProgressCallback& progress, const CancelToken* cancel,
                        std::optional<FitState> initial,
                        std::unique_ptr<FaceDetector> detector = nullptr, int frameLimit = -1);

}  // namespace clm3d
