// Drawing one reviewed frame with core's drawFitOverlay (the same drawing as `clm3d track
// --overlay`): the shown points are the ground-truth row (the track, or the hand correction), the
// patches are the templates of one short search from the frame's stored fit state (one iteration
// at the finest scale: a few ms at webcam sizes, measured by the page). The studio's frame view
// draws its patches with it on the GUI thread and its overlay export on a worker; the fitter passed
// in must be the caller's own (it is not thread-safe).
#pragma once

#include <opencv2/core/mat.hpp>
#include <optional>

#include "core/fit/fitter.hpp"
#include "core/review/track_session.hpp"
#include "core/track/fit_overlay.hpp"

namespace clm3d {

// The fitter settings of that short search.
FitSettings overlaySearchSettings();

// Draws on `bgr` (the frame, unchanged until the search has read it). Without a stored fit the
// start is the state that best reproduces the shown points (stateFromPoints), when
// `fitMissingStates`; otherwise such a frame gets no patches. A row without points draws the
// label only.
void drawReviewOverlay(cv::Mat& bgr, const TrackRow& shown, const std::optional<FrameFit>& fit,
                       Fitter& fitter, const Scheme& scheme, const FitOverlayOptions& options,
                       bool fitMissingStates);

}  // namespace clm3d
