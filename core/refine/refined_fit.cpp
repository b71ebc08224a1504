#include "core/refine/refined_fit.hpp"

#include <cmath>

#include "core/refine/descent_check.hpp"
#include "core/refine/view_check.hpp"

namespace clm3d {

void refineFit(const ClmModel& model, const cv::Mat& image, FitResult& fit,
               const RefinerStarts& starts) {
  // The view's own check reads the search's points, before they are refined.
  const double checked = viewCheckProbability(model, fit.view, image, fit.points);
  if (std::isfinite(checked)) fit.viewProbability = checked;
  const DescentRefiner& refiner = model.refiner;
  if (refiner.empty()) return;
  if (fit.view >= 0 && !model.views[static_cast<std::size_t>(fit.view)].refined) {
    if (std::isfinite(fit.viewProbability)) {
      fit.probability = fit.viewProbability;
      fit.probabilitySource = ProbabilitySource::ViewCheck;
    }
    return;
  }
  RefinedPoints refined = refineAndCheck(refiner, image, fit.points, true, starts);
  fit.points = std::move(refined.points);
  fit.refined = true;
  if (std::isfinite(refined.rightProbability)) {
    fit.probability = refined.rightProbability;
    fit.probabilitySource = ProbabilitySource::Check;
  }
}

double photoFitProbability(const ClmModel& model, const FitResult& fit, const cv::Mat& image) {
  if (fit.probabilitySource != ProbabilitySource::Check || fit.view < 0 ||
      fit.view >= static_cast<int>(model.views.size()))
    return fit.probability;
  const PhotoFitCurve* curve = nearestPhotoFitCurve(
      model.refiner.check.photoFitCurves, model.views[static_cast<std::size_t>(fit.view)].yawDeg);
  if (curve == nullptr) return fit.probability;
  const Eigen::VectorXf features = curve->hasImageTerm()
                                       ? photoFitFeatures(model, fit.view, image, fit.points)
                                       : Eigen::VectorXf();
  return photoFitProbability(*curve, fit.probability, features);
}

void judgeAsPhotoFit(const ClmModel& model, FitResult& fit, const cv::Mat& image) {
  const double p = photoFitProbability(model, fit, image);
  if (p == fit.probability) return;
  fit.probability = p;
  fit.probabilitySource = ProbabilitySource::PhotoFitCurve;
}

}  // namespace clm3d
