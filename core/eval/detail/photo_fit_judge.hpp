// The photo-fit curve with an image term (PhotoFitCurve, core/model/descent_refiner.hpp) learnt
// from the photo pipeline's fits in the views of one |yaw|: a logistic regression of right and
// wrong on the check's log-odds and on the fits' image features (photoFitFeatures), the features
// centred and reduced to their leading principal components, whose weights are penalised (ridge)
// by an amount chosen by five-fold cross-validation; the log-odds and the intercept are not
// penalised. The 50 components were chosen offline by cross-validation on the AFLW training faces'
// fits (session 44): at |yaw| 30 and 60 they ranked held-out fits better than 3 to 20 components
// and than all features, at |yaw| 0 about as well.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/model/descent_refiner.hpp"

namespace clm3d {

// Fits of one |yaw|: features (one row each, all of one length), the check's log-odds, labels.
struct PhotoFitSample {
  Eigen::MatrixXf features;
  std::vector<double> logOdds;
  std::vector<bool> right;
};

// The curve of `viewYawDeg` from the sample; its image weights in the features' own space (the
// components folded back), so that judging a fit needs no projection. Without an image term (the
// curve of the log-odds alone) when cross-validation does not show the term ranking held-out fits
// better by more than one standard error. Needs both labels.
PhotoFitCurve learnPhotoFitJudge(double viewYawDeg, const PhotoFitSample& sample);

}  // namespace clm3d
