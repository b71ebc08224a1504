// Training the model's point refiner (core/refine/descent_refinement.hpp) from the manifest's
// annotated photos: the refined points are those the photos' mark-up trusts
// (TrainingPhoto::trusted, as the patch experts learn them) in nearly every photo: for an iBUG 68
// mark-up, the 18 with an exact counterpart. Each photo is used as it is and left-right mirrored
// (photos that do not trust every refined point are left out), and the starts are its true points
// moved as a search typically leaves them.
#pragma once

#include <vector>

#include "core/common/progress.hpp"
#include "core/dataset/training_photos.hpp"
#include "core/model/descent_refiner.hpp"
#include "core/scheme/scheme.hpp"
#include "core/train/train_settings.hpp"

namespace clm3d {

// The refiner of settings.refinerStages stages, learnt from the photos whose source lets it
// (TrainingPhoto::refiner); empty when there are none or no such photo has the scheme's eye pair.
// Photos that cannot be read are skipped (the texture training reports them). Progress stage
// "refiner"; Cancelled when `cancel` fires.
DescentRefiner trainPhotoRefiner(const std::vector<TrainingPhoto>& photos, const Scheme& scheme,
                                 const TrainSettings& settings,
                                 const ProgressCallback& progress = {},
                                 const CancelToken* cancel = nullptr);

}  // namespace clm3d
