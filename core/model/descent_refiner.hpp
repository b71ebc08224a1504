// The learnt part of a model's point refinement (core/refine/descent_refinement.hpp): a cascade
// of linear regressions from gradient-orientation features around the points to their
// corrections, in the frame that maps the mean shape onto the current points, and the check that
// tells whether refined points sit on a face's landmarks (core/refine/descent_check.hpp). Plain
// data here, so that the model file reads and writes it without an image library.
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
  // (2 N) x (2 N): corrections from the current points' departure from the mean shape (in the
  // normalised frame, x then y per point), added to the features' (format 6); empty in models
  // written before, whose stages see the image only.
  Eigen::MatrixXf shapeWeights;
};

// The check's probability turned into the probability that a photo's whole fit (detection, face
// loop, search, refinement: `clm3d fit`, `clm3d batch`) is right, for the fits in the views of one
// |yaw|: a logistic curve of the check's log-odds, learnt by `clm3d calibrate` from that pipeline's
// own fits of annotated photos (model format 9). The check learns from refined starts around the
// truth of near-frontal photos and is too sure of the pipeline's fits of turned faces: on 1,185
// AFLW training faces it accepted 82 of the 179 fits off the face in the +-60 views.
//
// Model format 10 adds an image term: what the check cannot see on a turned face, read from the
// image at the fit's points with the layout of these views' own check (the gradient-orientation
// features at the landmarks the view sees, core/refine/view_check.hpp), learnt with the curve from
// the same fits: p = 1 / (1 + exp(-(slope * log(c / (1 - c)) + offset + imageWeights . (f -
// imageMean)))). On AFLW's test faces at |yaw| 60-90 it took the faces fitted right from 90 to 106
// and those reported although off the face from 42 to 36 (docs/fitting.md#the-image-term).
struct PhotoFitCurve {
  double viewYawDeg = 0.0;  // |yaw| of the views it judges (a view and its mirror image alike)
  double slope = 1.0, offset = 0.0;         // on the check's log-odds log(c / (1 - c))
  Eigen::VectorXf imageMean, imageWeights;  // empty: no image term (format 9, too few fits)

  bool hasImageTerm() const { return imageWeights.size() > 0; }
};

// A linear score of the features at the refined points, turned into the probability that the
// points are right (their mean error under a fixed share of the eye distance) by a logistic curve
// fitted to the training scores: p = 1 / (1 + exp(-(slope * score + offset))).
struct DescentCheck {
  double window = 0.5;          // feature window, in eye distances of the mean shape
  Eigen::VectorXf featureMean;  // subtracted before the score
  Eigen::VectorXf weights;      // one per feature
  double bias = 0.0;
  double slope = 1.0, offset = 0.0;
  // The refiner's check only: a photo fit's probability per |yaw| of its view (PhotoFitCurve);
  // empty: the check's own probability judges photos (models before format 9, uncalibrated ones).
  std::vector<PhotoFitCurve> photoFitCurves;

  bool empty() const { return weights.size() == 0; }
  // Throws Error naming the first inconsistency for a check of `points` points (sizes, window,
  // non-finite values).
  void validate(Eigen::Index points) const;
};

struct DescentRefiner {
  std::vector<int> landmarks;     // scheme indices of the refined points (N)
  int leftEye = 0, rightEye = 1;  // positions in `landmarks` of the eye centres
  Eigen::Matrix2Xd meanShape;     // 2 x N, eye distance 1, the eyes' midpoint at the origin
  std::vector<DescentStage> stages;
  DescentCheck check;  // empty: the model cannot tell right refined points from wrong ones

  bool empty() const { return stages.empty(); }
  // Whether the stages have shape weights (all or none do).
  bool hasShapeWeights() const { return !stages.empty() && stages.front().shapeWeights.size() > 0; }
  // Throws Error naming the first inconsistency (sizes, indices, non-finite values); `schemeSize`
  // bounds the landmark indices. An empty refiner is valid; a check needs stages.
  void validate(int schemeSize) const;
};

}  // namespace clm3d
