// A test sequence made from one annotated photo: the photo moving smoothly in the image plane
// (translation, scale, in-plane rotation) and changing in brightness and contrast, each frame an
// affine warp of the photo, with exact truth (the same affine applied to the photo's landmarks).
// Real skin and real backgrounds, but no head rotation in depth: it measures how a tracker
// follows a real face through image-plane motion and lighting change, where `clm3d synth`'s
// renders measure turning heads. `clm3d synth --photo` writes it (docs/synthetic-sequences.md).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <opencv2/core/matx.hpp>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

struct PhotoSequenceSettings {
  int frames = 120;
  std::uint64_t seed = 1;
  int width = 0;  // output frame size; 0 x 0 = the photo's size rounded down to even
  int height = 0;
  double fps = 30.0;
  // Largest excursion of each motion (the trajectory stays within +-these):
  double translationShare = 0.2;  // shift in x and in y, as a share of the face size
  double scaleRange = 0.15;       // relative size: scaleCentre +- this
  double scaleCentre = 1.0;       // (a zoom from 0.6 to 1.6 is centre 1.1, range 0.5)
  double rotationDeg = 20.0;      // in-plane rotation about the face centre
  double brightnessRange = 0.2;   // gain of the whole frame: 1 +- this
  double contrastRange = 0.2;     // gain about mid-grey: 1 +- this
  // Each motion is a sum of sinusoids whose periods are drawn from this range (frames).
  double minPeriodFrames = 40.0;
  double maxPeriodFrames = 160.0;

  // InputError for values out of range (frames, odd or too small size, negative ranges, ...).
  void validate() const;
};

// The motion of one frame.
struct PhotoMotion {
  double dx = 0.0;  // pixels, added to the face centre
  double dy = 0.0;
  double scale = 1.0;        // about the face centre
  double rotationDeg = 0.0;  // about the face centre; positive turns anticlockwise on screen
  double brightness = 1.0;   // output = brightness x (contrast x (input - 127.5) + 127.5)
  double contrast = 1.0;
};

// Every frame's motion: per motion a sum of three sinusoids with seeded random periods, phases and
// weights, scaled so it stays within its range. `faceSize` (pixels) scales the translation. The
// same settings and face size give the same trajectory on every platform (SplitMixRandom).
std::vector<PhotoMotion> photoTrajectory(const PhotoSequenceSettings& settings, double faceSize);

// The face the motion centres on: the centre and the larger side of the bounding box of the
// present points. Throws InputError (no file name: callers add it) for fewer than two present
// points or a box of no size.
struct PhotoFace {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double size = 0.0;
};
PhotoFace photoFace(const LandmarkSet& points);

// A photo's points for the sequence from `landmarksFile` (.pts/.ljson/.csv), 2D in the thesis25
// scheme: a 68-point file is converted and keeps only the points with a fixed 68-point
// counterpart (not the earlobes, which have none, nor the jaw contour's cheeks and chin sides).
// Throws InputError naming the file for a file that cannot be read or points photoFace refuses.
LandmarkSet readPhotoPoints(const std::filesystem::path& landmarksFile);

// The 2x3 affine from photo pixels to frame pixels (OpenCV convention, pixel centres at
// integers): p -> s R (p - c) + c + o + (dx, dy), with c the face centre and o the shift that
// centres the photo in a frame of another size ((frame - photo) / 2, in whole pixels).
cv::Matx23d photoTransform(const PhotoMotion& motion, const Eigen::Vector2d& faceCentre,
                           const cv::Size& photoSize, const cv::Size& frameSize);

// One frame: cv::warpAffine of the photo (bilinear, border replicated), then the brightness and
// contrast gains (saturated to 8 bits). photo: 8-bit BGR.
cv::Mat renderPhotoFrame(const cv::Mat& photo, const cv::Matx23d& transform,
                         const PhotoMotion& motion, const cv::Size& frameSize);

// Where the photo and its points came from, recorded in sequence.json.
struct PhotoSequenceSource {
  std::string photo;
  std::string landmarks;
};

struct PhotoSequenceSummary {
  int frames = 0;
  cv::Size frameSize;
  PhotoFace face;
  std::vector<PhotoMotion> motion;      // per frame
  std::vector<cv::Matx23d> transforms;  // per frame
  TrackTable truth;
};

// Writes the video (lossless FFV1 for .avi/.mkv, VideoWriter), the truth as a tracks CSV (success
// 1, confidence 1, view -1, no pose, the points moved by each frame's transform, missing points
// empty; extra columns m00,m01,m02,m10,m11,m12 with the transform and brightness, contrast), the
// visibility table (a present point is visible while inside the frame) and sequence.json.
// `points`: 2D, the scheme's order (thesis25 for `clm3d synth --photo`). Parent folders are
// created; files are saved atomically, the description last. Progress 0..1 over the frames;
// Cancelled (between frames) leaves no video. InputError for bad settings or a photo that is not
// 8-bit BGR.
PhotoSequenceSummary writePhotoSequence(const cv::Mat& photo, const LandmarkSet& points,
                                        const PhotoSequenceSettings& settings,
                                        const PhotoSequenceSource& source,
                                        const SequenceFiles& files,
                                        const ProgressCallback& progress = {},
                                        const CancelToken* cancel = nullptr);

}  // namespace clm3d
