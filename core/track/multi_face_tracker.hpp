// Tracking every face of a video (`clm3d track --faces all|N`): one Tracker per face, each going
// on from frame to frame exactly as a single-face track does, and one face detector over the whole
// frame every few frames, whose faces that no track holds start new tracks. A face keeps its id
// while its track goes on, whatever the faces around it do (two people crossing keep theirs); a
// face that is lost and found again near where it was lost gets its id back. A track that fails
// is offered again, in the same frame, only the detected faces near it that no other track holds,
// so it can neither take over another person nor double up on a face another id follows.
// Safe on a worker thread; the model must outlive the tracker.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/track/tracker.hpp"

namespace clm3d {

struct MultiFaceSettings {
  int maxFaces = 0;  // faces tracked at once; 0 = every face found
  // Frames between searches of the whole frame for faces not yet tracked: a face that comes into
  // view is picked up within this many frames. A frame with no face tracked is always searched.
  int detectEvery = 5;
  // A lost face's id is given to a face found within this many of its last eye distances of
  // where it was lost (measured centre to centre); farther, the face gets a new id.
  double reidentifyEyeDistances = 2.5;
};

// One face's step in a frame: the face's id (0, 1, ... in the order faces were first found) and
// what its tracker did (TrackStep, as for a single face; row.extraCells is left empty).
struct FaceStep {
  int face = 0;
  TrackStep step;
};

// What TrackerSettings::faces (`clm3d track --faces`, the studio's "Faces to track") asks for:
// whether the video is tracked face by face (trackVideoFaces, rows with a `face` column) rather
// than as one face (trackVideo, no face column), and the MultiFaceSettings it is tracked with.
bool tracksFaceByFace(const TrackerSettings& settings);
MultiFaceSettings multiFaceSettings(const TrackerSettings& settings);

class MultiFaceTracker {
 public:
  // InputError for a negative maxFaces or a detectEvery below 1.
  MultiFaceTracker(const ClmModel& model, const Camera& camera, const TrackerSettings& settings,
                   const MultiFaceSettings& faces = {});
  ~MultiFaceTracker();
  MultiFaceTracker(const MultiFaceTracker&) = delete;
  MultiFaceTracker& operator=(const MultiFaceTracker&) = delete;

  // Tracks one frame (BGR or grey, the camera's size). One step per face in the frame, by id: the
  // faces tracked in the frame before (passing or failing now) and the faces found in this one.
  // A face lost in an earlier frame has no step until it is found again.
  std::vector<FaceStep> track(const cv::Mat& frame, int index, double timestamp);

  // The tracker of a face id that track() returned (its fitter drew the face's templates).
  Tracker& tracker(int face);
  int facesSeen() const { return static_cast<int>(faces_.size()); }

 private:
  struct Face;
  // Faces of this frame's detection (run at most once a frame, on demand).
  const std::vector<FaceBox>& detected(const cv::Mat& frame);

  const ClmModel* model_;
  Camera camera_;
  TrackerSettings settings_;
  MultiFaceSettings multi_;
  FaceDetector detector_;
  std::vector<std::unique_ptr<Face>> faces_;  // index = id
  std::optional<std::vector<FaceBox>> detected_;
  int lastSearch_ = -1;  // the last frame searched for new faces
};

// Tracks every face of a video: each face's rows, in frame order and by id within a frame, go to
// `onRow` with the id in the row's first extra cell (the tracks table's `face` column). perFrame
// sees each frame once, with its faces' steps (none when no face is tracked) and the tracker, e.g.
// to draw the overlay. Summary: frames decoded; succeeded, detections and fit times count
// face-frames. With frameLimit >= 0 only the frames before it. Throws as trackVideo.
using FacePerFrame =
    std::function<void(const cv::Mat&, const std::vector<FaceStep>&, MultiFaceTracker&)>;
TrackSummary trackVideoFaces(const std::filesystem::path& video, const ClmModel& model,
                             const TrackerSettings& settings, const MultiFaceSettings& faces,
                             const TrackRowSink& onRow, const FacePerFrame& perFrame = {},
                             const ProgressCallback& progress = {},
                             const CancelToken* cancel = nullptr, int frameLimit = -1);

}  // namespace clm3d
