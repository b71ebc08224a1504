// Drawing a fit over its frame as in the thesis's figure 5.5: each landmark's synthetic patch
// (the template the search matched) pasted in place at the size it was matched at, the landmarks
// on top, and a label with the frame (or the photo), the view and the confidence. The tracker's
// overlay video, the studio's frame view and `clm3d fit --overlay` draw with this one code, from
// the fit's result alone.
#pragma once

#include <opencv2/core/mat.hpp>
#include <string>

#include "core/scheme/scheme.hpp"
#include "core/track/tracker.hpp"

namespace clm3d {

struct FitOverlayOptions {
  bool patches = true;
  bool landmarks = true;
  bool label = true;
};

// Draws a tracked frame on `bgr`, a BGR copy of `frame` (the image the step's fit searched; it may
// be `bgr` itself when one fit is drawn): the patches are the fit's templates, which `fitter` (the
// one that searched, or one of the same model, camera and settings) makes from `frame` where the
// search read it (Fitter::templates), not the fitter's last search.
void drawFitOverlay(cv::Mat& bgr, const cv::Mat& frame, const TrackStep& step, Fitter& fitter,
                    const Scheme& scheme, const FitOverlayOptions& options = {});

// The same drawing for a photo's fit (`clm3d fit --overlay`), labelled with `name` and marked
// REJECTED unless the fit `passed` the point check.
void drawPhotoOverlay(cv::Mat& bgr, const cv::Mat& photo, const FitResult& fit, bool passed,
                      const std::string& name, Fitter& fitter, const Scheme& scheme,
                      const FitOverlayOptions& options = {});

}  // namespace clm3d
