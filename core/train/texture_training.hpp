// Builds the texture models of every view: renders each subject from each view with perturbed
// samples on a pool of worker threads (one renderer per worker and subject), extracts patches at
// every scale, marks landmarks hidden in more than settings.hiddenShare of a view's samples, and
// fits a patch PCA per view and scale. Right-side views may be mirrors of left-side ones.
#pragma once

#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/mesh/textured_mesh.hpp"
#include "core/model/texture_model.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"
#include "core/train/train_settings.hpp"
#include "core/train/training_sample.hpp"

namespace clm3d {

// A textured training subject, by reference (meshes are large); landmarks in model coordinates.
struct TrainingSubject {
  std::string id;
  const TexturedMesh* mesh = nullptr;
  const LandmarkSet* landmarks = nullptr;
};

// A training photo already brought into the training frame (core/train/photo_samples.hpp):
// upright, at the training scale, assigned to a rendered view (never a mirrored one). Its
// patches' `visible` flags mark the landmarks whose points are trusted to train patches.
struct PhotoSample {
  std::string id;
  int view = 0;  // index into settings.views()
  SamplePatches patches;
};

// Per view of settings.views(), in that order. progress gets fractions in [0, 1] with stage
// "rendering" then "pca". Deterministic for a given settings.seed whatever the thread count.
// Throws Cancelled when the token is set (checked before every render), InputError for bad
// subjects (no subjects, wrong landmark count, eye centres missing and not imputable from the
// other subjects). A missing landmark does not count as hidden; its patches in that subject's
// samples are the mean of the other subjects' patches.
// `framingDonors` (the shape-only sets) may supply the eye centres of a subject that lacks them,
// for framing its renders, when no other textured subject can.
// `photos` join their views' PCA data and experts for their trusted landmarks; the hidden
// landmarks and alpha masks come from the renders only. With settings.expertRadius > 0 every
// scale of every view also gets a patch expert per landmark (progress stage "experts").
std::vector<ViewModel> trainTextureModels(const std::vector<TrainingSubject>& subjects,
                                          const Scheme& scheme, const TrainSettings& settings,
                                          const ProgressCallback& progress = {},
                                          const CancelToken* cancel = nullptr,
                                          const std::vector<LandmarkSet>& framingDonors = {},
                                          const std::vector<PhotoSample>& photos = {});

}  // namespace clm3d
