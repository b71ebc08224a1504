// Annotated photos brought into the training frame of the texture models (issue 12): each photo's
// 3D pose and shape fitted to its trusted points (stateFromPoints), the photo turned upright (its
// in-plane rotation removed) and scaled so that the face has the training inter-ocular distance
// (settings.interOcularPixels() for the fitted 3D eye distance, as the renders are framed), then
// its patches and expert regions sampled at every scale. It joins the view nearest its pitch and
// yaw; its left-right mirror image (landmarks swapped by the scheme's mirror pairs) joins the view
// nearest the mirrored pose. With mirrored right-side views (the default) a copy whose nearest
// view is a mirror is dropped, since its mirror image trains that view's source. A source's
// `per_view` caps the copies of its photos that join each view, the first in input order (the
// poses are fitted for all of them first, then only the kept copies are sampled).
#pragma once

#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/dataset/training_photos.hpp"
#include "core/model/shape_model.hpp"
#include "core/train/texture_training.hpp"

namespace clm3d {

struct PhotoPlacement {  // what happened to one photo, for the training report
  std::string id;
  double pitchDeg = 0, yawDeg = 0, rollDeg = 0;  // fitted pose
  int samples = 0;                               // copies that joined a view (0, 1 or 2)
  int capped = 0;       // copies left out because their source filled their view (`per_view`)
  std::string skipped;  // why none did (unreadable, too few points)
};

// On settings.threads threads; the result is in photo order (original, then mirror) whatever the
// thread count. `schemeJson` and `shape` are the model being trained. A photo that cannot be used
// (unreadable image, fewer than 6 trusted points, a fit that does not converge to a face) is
// skipped and reported in `placements`, not fatal. Throws Cancelled when cancelled.
std::vector<PhotoSample> preparePhotoSamples(const std::vector<TrainingPhoto>& photos,
                                             const std::string& schemeJson, const ShapeModel& shape,
                                             const TrainSettings& settings,
                                             std::vector<PhotoPlacement>* placements = nullptr,
                                             const ProgressCallback& progress = {},
                                             const CancelToken* cancel = nullptr);

}  // namespace clm3d
