// Adapting a trained model to the person of one video (issue 29, `clm3d adapt`): the frames a
// person corrected by hand become training photos (each frame's points fitted to a 3D pose, which
// gives its view; with its left-right mirror image and jittered placements, as the trainer places
// annotated photos, core/train/photo_samples.hpp), and every patch expert and template mean of the
// views they fall in moves towards them by maximum a posteriori adaptation: the general model's
// expert is a prior worth `priorRegions` training regions (core/train/detail/expert_training.hpp,
// adaptPatchExpert) and its template mean a prior worth as many patches, so a handful of frames
// nudges the model and the general training is not forgotten. The point refiner is adapted the same
// way (core/refine/descent_refinement.hpp, adaptDescentRefiner: the general cascade a prior worth
// `refinerPrior` faces). Views and landmarks no frame shows, the shape model, the PCA modes, the
// refiner's check and the views' calibration stay the general model's. Deterministic for a seed
// whatever the thread count; safe on a worker thread.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d {

struct AdaptationFrame {
  int frame = 0;            // its index in the video (recorded in the adapted model)
  cv::Mat image;            // 8-bit BGR (or grey); the caller keeps it alive during the call
  Eigen::Matrix2Xd points;  // 2 x scheme size, pixels; a NaN column is a missing point
};

struct AdaptSettings {
  int jitter = 4;  // perturbed placements of each frame and its mirror image beside the exact one
  // The weight of the general model's experts and template means, in training regions (a region:
  // one frame copy's patch around one landmark). 20 frames give a frontal view's landmark about
  // 20 x 2 x (1 + jitter) = 200 regions, so 30 gives the video seven eighths of the weight. Chosen
  // on two real webcam clips (cap12, cap13) in the correction loop: frames corrected 38 and 33
  // against 100+ and 61 with 300, the default before, and the uncorrected frames' error 29-31%
  // below the general model's against 23% (docs/adapt.md, "Chosen on real video").
  double priorRegions = 30.0;
  int minRegions = 8;  // a landmark with fewer regions in a view keeps its general expert there
  // The general point refiner's weight, in faces (a corrected frame and its mirror image are two):
  // each stage adds the regression of what it leaves on the frames, ridge-regularised towards no
  // change by this weight. 0 = the refiner is not adapted.
  double refinerPrior = 30.0;
  std::uint64_t seed = 1;
  int threads = 0;  // 0 = one per core; the result does not depend on it

  // Throws InputError naming the setting that is out of range.
  void validate() const;
};

struct AdaptationSummary {
  int frames = 0;                    // frames given
  std::vector<int> framesUsed;       // frames placed in a view, ascending
  std::vector<std::string> skipped;  // "frame 12: why" for every frame not used
  int samples = 0;                   // placed copies (frames, mirror images, jittered copies)
  int expertsAdapted = 0;            // per stored view, scale and landmark
  int expertsKept = 0;               // too few regions there: the general expert
  int templatesAdapted = 0;          // landmark template means moved
  int refinerFaces = 0;  // faces (frames with every refined point, and their mirror images) the
                         // point refiner was adapted to; 0: not adapted
};

// The general model adapted to `frames`. Progress stages "photos" (placing the frames) and
// "experts". Throws InputError when there are no frames, a frame's points do not match the
// model's scheme, the model's experts have more than one unit (neural fields are not adapted),
// its views are not a pitch x yaw grid, or no frame can be placed (the reasons given); Cancelled
// when cancelled. The result's `adaptation.frames` lists the frames used; its other provenance
// (the general model's file, the video) is the caller's to fill.
ClmModel adaptModel(const ClmModel& general, const std::vector<AdaptationFrame>& frames,
                    const AdaptSettings& settings, AdaptationSummary* summary = nullptr,
                    const ProgressCallback& progress = {}, const CancelToken* cancel = nullptr);

}  // namespace clm3d
