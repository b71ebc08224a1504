// A search's fit finished by the model's point refiner: the points refined and, where the refiner
// has a check, the fit's confidence replaced by the check's probability that the refined points
// are right (the search's own kept as FitResult::searchConfidence). Still images, batches and the
// tracker finish every fit this way, so that the confidence they compare starts by, report and
// judge failures on is that of the points they output.
#pragma once

#include <opencv2/core/mat.hpp>

#include "core/fit/fitter.hpp"
#include "core/model/descent_refiner.hpp"
#include "core/refine/descent_refinement.hpp"

namespace clm3d {

// Refines `fit` in place (nothing changes when the refiner is empty); `image` is the searched one,
// `starts` as refineAndCheck takes them.
void refineFit(const DescentRefiner& refiner, const cv::Mat& image, FitResult& fit,
               const RefinerStarts& starts = {});

}  // namespace clm3d
