// A logistic curve p = 1 / (1 + exp(-(slope * score + offset))) that turns a score into the
// probability of a label, and its maximum-likelihood fit to labelled scores. The point check's
// calibration and the views' calibration (core/train/view_calibration.hpp) both fit one.
#pragma once

#include <vector>

namespace clm3d {

struct LogisticCurve {
  double slope = 1.0, offset = 0.0;

  double operator()(double score) const;
};

struct LogisticFitSettings {
  // Ridge on the slope, so that separable scores give a steep but finite curve.
  double slopeRidge = 1e-3;
  // Each class weighted by half over its count, so that the curve does not follow the class
  // ratio of the sample (false: every score counts once).
  bool balanced = false;
  int maxIterations = 50;
};

// log(p / (1 - p)), p clamped to [1e-12, 1 - 1e-12] so that a certain 0 or 1 stays finite.
double logOdds(double probability);

// Newton's method from slope 1, offset 0. With fewer than one score of each label the start is
// returned.
LogisticCurve fitLogisticCurve(const std::vector<double>& scores, const std::vector<bool>& labels,
                               const LogisticFitSettings& settings = {});

}  // namespace clm3d
