// Reading a view's own check (core/model/view_check.hpp): the features of a search's points at
// the view's visible landmarks, in a face-sized crop (flipped left-right for a mirrored view, so
// that a view and its mirror image share one check), and the probability the check gives them.
// Training (core/train/view_calibration.cpp) and every fit read them through these functions, so
// that what a check learnt from is what it is shown.
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include "core/model/clm_model.hpp"

namespace clm3d {

// The crop's face size (sqrt(width height) of the read points' box), in pixels.
inline constexpr double kViewCheckFacePixels = 96.0;
// The feature window, in units of the face size (about 0.6 of a frontal eye distance).
inline constexpr double kViewCheckWindow = 0.25;

// The landmarks and mean shape of the check of `view` (a non-mirrored view of `model`); its
// classifier is left empty, for training to fill.
ViewCheck viewCheckLayout(const ClmModel& model, int view);

// The features `check` reads from `points` (2 x L, every scheme landmark, image pixels) of a fit
// that ended in `view` of `model`, in `image` (8-bit grey, BGR or BGRA, or float). Empty when a
// read point is not finite or the points' box is empty.
Eigen::VectorXf viewCheckFeatures(const ClmModel& model, int view, const ViewCheck& check,
                                  const cv::Mat& image, const Eigen::Matrix2Xd& points);

// The image features of a photo fit that ended in `view` (PhotoFitCurve's image term): the check
// layout of ClmModel::photoFitLayoutView for the view's |yaw|, read at `points` (a mirrored view's
// fit flipped, as viewCheckFeatures does). Empty when the model has no such view or the points
// cannot be read.
Eigen::VectorXf photoFitFeatures(const ClmModel& model, int view, const cv::Mat& image,
                                 const Eigen::Matrix2Xd& points);

// The probability that a fit in `view` with `points` is right, by the view's check; NaN when the
// view has none or its features cannot be read.
double viewCheckProbability(const ClmModel& model, int view, const cv::Mat& image,
                            const Eigen::Matrix2Xd& points);

}  // namespace clm3d
