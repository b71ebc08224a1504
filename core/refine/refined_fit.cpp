#include "core/refine/refined_fit.hpp"

#include <cmath>

namespace clm3d {

void refineFit(const DescentRefiner& refiner, const cv::Mat& image, FitResult& fit,
               const RefinerStarts& starts) {
  if (refiner.empty()) return;
  RefinedPoints refined = refineAndCheck(refiner, image, fit.points, true, starts);
  fit.points = std::move(refined.points);
  if (std::isfinite(refined.rightProbability)) {
    fit.searchConfidence = fit.searchScore();
    fit.confidence = refined.rightProbability;
  }
}

}  // namespace clm3d
