// The learnt part of a model's point refinement (core/refine/descent_refinement.hpp): a cascade
// of linear regressions from gradient-orientation features around the points to their
// corrections, in the frame that maps the mean shape onto the current points. Plain data here, so
// that the model file reads and writes it without an image library.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace clm3d {

// Features per refined point: 4 x 4 cells of 8 orientation bins.
inline constexpr int kDescentFeaturesPerPoint = 128;

struct DescentStage {
  double window = 0.5;          // feature window, in eye distances of the mean shape
  Eigen::VectorXf featureMean;  // subtracted before the regression
  Eigen::MatrixXf weights;      // (2 N) x features: corrections, x then y per point
  Eigen::VectorXf bias;         // 2 N
};

struct DescentRefiner {
  std::vector<int> landmarks;     // scheme indices of the refined points (N)
  int leftEye = 0, rightEye = 1;  // positions in `landmarks` of the eye centres
  Eigen::Matrix2Xd meanShape;     // 2 x N, eye distance 1, the eyes' midpoint at the origin
  std::vector<DescentStage> stages;

  bool empty() const { return stages.empty(); }
  // Throws Error naming the first inconsistency (sizes, indices, non-finite values); `schemeSize`
  // bounds the landmark indices. An empty refiner is valid.
  void validate(int schemeSize) const;
};

}  // namespace clm3d
