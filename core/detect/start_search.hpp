// Searching from several starts around a detector's: the box places the mean shape only roughly
// (0.15 of the eye distance off on average on real photos, docs/initialisation.md), which is more
// than a search's capture range. Fitting from a small grid of moved and rescaled copies of the
// start and keeping the fit the optimiser is most confident in trades a few searches per detection
// for a start inside that range; on a tracked video it runs only on frames that were detected.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <opencv2/core/mat.hpp>

#include "core/fit/fitter.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d {

struct StartSearchSettings {
  // Shifts of the start in the image plane on a (2 steps + 1)^2 grid, `shift` of the start's
  // projected eye distance apart. steps 0 searches from the start alone.
  int steps = 0;
  double shift = 0.15;
  // Each shifted start is also searched at these relative sizes (1 = as placed), e.g. {0.9, 1.1}.
  // Empty: the placed size only.
  std::vector<double> sizes;
};

// `start` moved in the image plane by shareOfEyes (x right, y down) times its projected
// eye-centre distance, at the same depth.
FitState shiftedStart(const ClmModel& model, const Fitter& fitter, FitState start,
                      const Eigen::Vector2d& shareOfEyes);

// What is done to each search's fit before fits are compared (the point refiner's refineFit: its
// check's probability is then the confidence compared). Empty: nothing.
using FitFinisher = std::function<void(FitResult&)>;

// Searches `image` from `start` and from every start of the grid, finishes every fit with
// `finish`, and returns the one with the highest confidence (the first on ties, so steps 0 with no
// sizes is fitter.fit(image, start) finished). `searches`, when given, receives the number of
// searches made.
FitResult fitFromBestStart(Fitter& fitter, const ClmModel& model, const cv::Mat& image,
                           const FitState& start, const StartSearchSettings& settings,
                           int* searches = nullptr, const FitFinisher& finish = {});

}  // namespace clm3d
