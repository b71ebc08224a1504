// A logistic curve p = 1 / (1 + exp(-(slope * score + offset))) that turns a score into the
// probability of a label, and its maximum-likelihood fit to labelled scores. The point check's
// calibration and the views' calibration (core/train/view_calibration.hpp) both fit one. The
// curve is the one-input case of a penalised logistic regression, which the photo-fit judge
// (core/eval/photo_fit_calibration.hpp) fits on many inputs.
#pragma once

#include <Eigen/Core>
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

// p_i = 1 / (1 + exp(-x_i . w)) for the rows x_i of `inputs` (n x m; a column of ones gives an
// intercept), w maximising the likelihood of `labels` less (1/2) sum_j penalties_j w_j^2 (per
// class half over its count with `balanced`); Newton's method from `start`, each step halved
// while it does not lower the loss. With fewer than one label of each kind, `start` is returned.
Eigen::VectorXd fitLogisticRegression(const Eigen::MatrixXd& inputs,
                                      const std::vector<bool>& labels,
                                      const Eigen::VectorXd& penalties,
                                      const Eigen::VectorXd& start, bool balanced = false,
                                      int maxIterations = 50);

}  // namespace clm3d
