#include "core/refine/refined_fit.hpp"

#include <cmath>

namespace clm3d {

void refineFit(const ClmModel& model, const cv::Mat& image, FitResult& fit,
               const RefinerStarts& starts) {
  const DescentRefiner& refiner = model.refiner;
  if (refiner.empty()) return;
  if (fit.view >= 0 && !model.views[static_cast<std::size_t>(fit.view)].refined) {
    if (std::isfinite(fit.viewProbability)) {
      fit.searchConfidence = fit.searchScore();
      fit.confidence = fit.viewProbability;
    }
    return;
  }
  RefinedPoints refined = refineAndCheck(refiner, image, fit.points, true, starts);
  fit.points = std::move(refined.points);
  if (std::isfinite(refined.rightProbability)) {
    fit.searchConfidence = fit.searchScore();
    fit.confidence = refined.rightProbability;
  }
}

}  // namespace clm3d
