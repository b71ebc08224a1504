// A search's fit finished by the model's point refiner: the points refined and, where the refiner
// has a check, the fit's probability (FitResult::probability) replaced by the check's probability
// that the refined points are right (the search's own score stays in FitResult::searchScore).
// Still images, batches and the tracker finish every fit this way, so that the probability they
// compare starts by, report and judge failures on is that of the points they output.
#pragma once

#include <opencv2/core/mat.hpp>

#include "core/fit/fitter.hpp"
#include "core/model/clm_model.hpp"
#include "core/refine/descent_refinement.hpp"

namespace clm3d {

// Finishes `fit` in place with `model`'s refiner (nothing changes when it has none); `image` is
// the searched one, `starts` as refineAndCheck takes them. In a view the refiner did not learn
// (ViewModel::refined false: a profile, for a refiner learnt from near-frontal photos) the points
// stay the search's, and the fit's probability becomes the view's own check's
// (FitResult::viewProbability) when it has one.
void refineFit(const ClmModel& model, const cv::Mat& image, FitResult& fit,
               const RefinerStarts& starts = {});

// The probability that judges `fit` as a photo's (`clm3d fit`, `clm3d batch`): the check's through
// the model's photo-fit curve of the fit's view (photoFitProbability,
// core/refine/descent_check.hpp), with the curve's image term read in `image` at the fit's
// points, when the fit's probability is the check's and the model has curves; else
// fit.probability.
double photoFitProbability(const ClmModel& model, const FitResult& fit, const cv::Mat& image);

// `fit` judged as a photo's: its probability set to photoFitProbability and its source to
// ProbabilitySource::PhotoFitCurve when that differs from its own.
void judgeAsPhotoFit(const ClmModel& model, FitResult& fit, const cv::Mat& image);

}  // namespace clm3d
