#include "core/review/review_overlay.hpp"

#include "core/detect/initialisation.hpp"

namespace clm3d {

FitSettings overlaySearchSettings() {
  FitSettings settings;
  settings.scales = 1;
  settings.maxIterations = 1;
  return settings;
}

void drawReviewOverlay(cv::Mat& bgr, const TrackRow& shown, const std::optional<FrameFit>& fit,
                       Fitter& fitter, const Scheme& scheme, const FitOverlayOptions& options,
                       bool fitMissingStates) {
  TrackStep step;
  step.row = shown;
  std::vector<bool> present(static_cast<std::size_t>(shown.points.cols()));
  int presentCount = 0;
  for (int i = 0; i < shown.points.cols(); ++i) {
    present[static_cast<std::size_t>(i)] = shown.points.col(i).allFinite();
    presentCount += present[static_cast<std::size_t>(i)] ? 1 : 0;
  }
  if (presentCount == 0) {
    step.failure = TrackFailure::NoFace;
    drawFitOverlay(bgr, bgr, step, fitter, scheme, options);
    return;
  }
  std::optional<FrameFit> start = fit;
  if (!start && fitMissingStates && presentCount >= 4) {
    start = FrameFit{stateFromPoints(fitter.model(), fitter.camera(), shown.points, present), -1};
  }
  if (start) {
    FitResult result = fitter.fit(bgr, start->state, start->view);
    result.points = shown.points;  // the patches sit where the shown points are
    step.fit = std::move(result);
  } else {
    // No state to search from: the landmarks alone, no templates.
    FitResult result;
    result.points = shown.points;
    result.modelled = present;
    result.view = 0;
    result.probability = shown.confidence;
    step.fit = std::move(result);
    FitOverlayOptions withoutPatches = options;
    withoutPatches.patches = false;
    withoutPatches.label = false;
    drawFitOverlay(bgr, bgr, step, fitter, scheme, withoutPatches);
    return;
  }
  step.fit->probability = shown.confidence;
  drawFitOverlay(bgr, bgr, step, fitter, scheme, options);
}

}  // namespace clm3d
