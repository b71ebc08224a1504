// Drawing a fit over its frame as in the thesis's figure 5.5: each landmark's synthetic patch
// (the template the search matched) pasted in place at the size it was matched at, the landmarks
// on top, and a label with the frame, the view and the confidence. The tracker's overlay video
// and the studio's frame view draw with this one function.
#pragma once

#include <opencv2/core/mat.hpp>

#include "core/scheme/scheme.hpp"
#include "core/track/tracker.hpp"

namespace clm3d {

struct FitOverlayOptions {
  bool patches = true;
  bool landmarks = true;
  bool label = true;
};

// Draws on a BGR frame. `fitter` supplies the last search's templates, so call it right after the
// search that produced `step`.
void drawFitOverlay(cv::Mat& bgr, const TrackStep& step, const Fitter& fitter, const Scheme& scheme,
                    const FitOverlayOptions& options = {});

}  // namespace clm3d
