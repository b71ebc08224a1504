// One perturbed training render: where the face is put (pose, camera, light) for a given view,
// subject and sample, drawn from a random stream keyed by (seed, subject, view, sample) so the
// result does not depend on thread scheduling; and the patches (normalised grey and alpha) and
// landmark visibility extracted from the render at every pyramid scale.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/train/augmentation.hpp"
#include "core/train/train_settings.hpp"

namespace clm3d {

struct SampleSpec {
  double pitchDeg = 0, yawDeg = 0, rollDeg = 0;
  double scale = 1.0;                     // multiplies the target inter-ocular distance
  Eigen::Vector2d shiftPixels{0.0, 0.0};  // image-plane shift at the finest scale
  Lighting lighting;
  AugmentationDraw augmentation;  // none unless settings.augmentation switches effects on
};

// The perturbed sample `sample` of `view` for subject `subject`: deterministic in its arguments.
SampleSpec drawSample(const TrainSettings& settings, const ViewCentre& view, std::uint64_t seed,
                      int subject, int viewIndex, int sample);

struct SampleFrame {
  Pose pose;
  Camera camera;
};

// Puts the landmarks' centroid at the image centre (plus the shift) and the face at the distance
// where the 3D inter-ocular distance (the scheme's normalisation pair) measures
// settings.interOcularPixels() * spec.scale pixels. Throws InputError if the pair is missing.
SampleFrame frameSample(const LandmarkSet& landmarks, std::pair<int, int> eyes,
                        const SampleSpec& spec, const TrainSettings& settings);

struct SamplePatches {
  std::vector<bool> visible;           // per landmark (missing landmarks are not visible)
  std::vector<Eigen::MatrixXf> grey;   // per scale: patchSize^2 x landmarks, each normalised
  std::vector<Eigen::MatrixXf> alpha;  // per scale: patchSize^2 x landmarks, in [0, 1]; empty
                                       // for photos (no coverage)
  // Per scale, when settings.expertRadius > 0: (patchSize + 2 radius)^2 x landmarks raw grey
  // regions (sampleRegion, upright) around each landmark, for the patch experts.
  std::vector<Eigen::MatrixXf> regions;
};

// The patches of `points` (level-0 pixels, 2 x landmarks) in a grey CV_32F image and, when
// `alpha` is not empty, its coverage: every scale of a Gaussian pyramid, landmarks with
// has[i] false left as zeros and not visible; `visible` is `has` (callers that know better, the
// renders' depth test, overwrite it).
SamplePatches extractPatches(const cv::Mat& grey, const cv::Mat& alpha,
                             const Eigen::Matrix2Xd& points, const std::vector<bool>& has,
                             const TrainSettings& settings);

// The render of a sample (with cast shadows if drawn) and the image its grey patches are taken
// from: the render itself, or with augmentation the 8-bit BGR image after augmentImage.
struct TrainingImage {
  SampleFrame frame;
  RenderResult render;  // alpha = coverage (the masks), depth (visibility)
  cv::Mat image;        // BGRA (no image effects) or BGR
};
TrainingImage renderTrainingImage(OffscreenRenderer& renderer, const LandmarkSet& landmarks,
                                  std::pair<int, int> eyes, const SampleSpec& spec,
                                  const TrainSettings& settings);

// Renders the sample and extracts its patches; visibility from the depth buffer.
SamplePatches renderSample(OffscreenRenderer& renderer, const LandmarkSet& landmarks,
                           std::pair<int, int> eyes, const SampleSpec& spec,
                           const TrainSettings& settings);

}  // namespace clm3d
