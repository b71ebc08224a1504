// A test sequence that turns a real photo's face in 3D: the photo profiled (photo_profile.hpp)
// and rendered over its own background at the head angles of a synthetic sequence
// (sequenceAngles: a range or a sweep, `step` degrees a frame), with exact truth for the dense
// face: its landmarks projected and their visibility from the render's depth. Written in the
// layout of `clm3d synth` (SequenceFiles: video, truth.csv, truth-visibility.csv, sequence.json),
// so `clm3d track` and `clm3d eval` read it as any other. `clm3d synth --photo --yaw-range` writes
// it (docs/synthetic-sequences.md).
#pragma once

#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "core/profile/dense_face.hpp"
#include "core/profile/detail/photo_profile.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

struct TurnedPhotoSettings {
  // Head angles (degrees, pose.hpp signs), absolute: yaw 0 faces the camera. Without a pitch
  // range (keepPhotoPitch) every frame keeps the pitch fitted to the photo.
  double yawFromDeg = -60.0;
  double yawToDeg = 60.0;
  bool keepPhotoPitch = true;
  double pitchFromDeg = 0.0;
  double pitchToDeg = 0.0;
  double stepDeg = 1.0;
  SequenceOrder order = SequenceOrder::Range;
  double verticalFovDeg = kDefaultVerticalFovDeg;  // the photo's assumed camera
  double fps = 30.0;
  ProfileSettings profile;
  // > 0: the summary's contact sheet holds the photo and this many frames spread over the
  // sequence, each with its visible truth points marked.
  int sheetFrames = 0;

  void validate() const;  // InputError for values out of range
};

// Where the photo, its points and the dense face came from, recorded in sequence.json.
struct TurnedPhotoSource {
  std::string photo;
  std::string landmarks;
  std::string denseModel;
};

struct TurnedPhotoSummary {
  int frames = 0;
  cv::Size frameSize;
  PhotoProfile profile;  // the fit, the textured face and the background
  TrackTable truth;
  std::vector<std::vector<bool>> visible;  // per frame, per landmark
  int hiddenPoints = 0;                    // present landmark-frames not visible
  cv::Mat contactSheet;                    // BGR, when settings.sheetFrames > 0
};

// The frames a turned photo's sequence has: its yaw (and pitch) range at its step.
int turnedPhotoFrameCount(const TurnedPhotoSettings& settings);

// Profiles `photo` (8-bit BGR; cropped to even sides, the video codecs' need) from `points` (2D,
// the dense face's scheme, thesis25 for `clm3d synth`) with a camera of the photo's size and the
// settings' field of view, then renders and writes every frame: the truth (success 1, confidence
// 1, view -1, the frame's pose, the projected landmarks; hidden ones keep their position), the
// visibility table and sequence.json (the fit, the profile and the angles). Parent folders are
// created; files are saved atomically, the description last. Progress 0..1; Cancelled between
// frames leaves no video. InputError for bad settings, a photo that is not 8-bit BGR or under
// 16x16, or points the fit refuses.
TurnedPhotoSummary writeTurnedPhotoSequence(const DenseFace& face, const cv::Mat& photo,
                                            const LandmarkSet& points,
                                            const TurnedPhotoSettings& settings,
                                            const TurnedPhotoSource& source,
                                            const SequenceFiles& files,
                                            const ProgressCallback& progress = {},
                                            const CancelToken* cancel = nullptr);

}  // namespace clm3d
