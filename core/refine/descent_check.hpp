// The point refiner's check: whether refined points sit on a face's landmarks. A search's own
// confidence (the experts' mean response, the templates' NCC) scores the search's points, not the
// refined ones, and is about as high on a face the search misplaced as on one it found; the check
// scores what is reported. It is a linear classifier of the refiner's gradient-orientation
// features at the refined points, learnt from annotated photos: refined starts near the truth
// that ended right and starts moved far (a whole eye distance and more, a wrong scale or roll)
// that ended wrong, as OpenFace learns its failure checker from aligned and displaced faces. Its
// score is turned into a probability by a logistic curve fitted on photos the classifier did not
// learn from.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/common/logistic_curve.hpp"
#include "core/common/progress.hpp"
#include "core/model/descent_refiner.hpp"
#include "core/refine/descent_refinement.hpp"
#include "core/refine/training_starts.hpp"

namespace clm3d {

// The probability that `points` (the refiner's N points, region pixels of `regionGrey`, as
// refineInRegion gives them) are right; NaN when the refiner has no check.
double checkInRegion(const DescentRefiner& refiner, const cv::Mat& regionGrey,
                     const Eigen::Matrix2Xd& points);

// The photo-fit curve (PhotoFitCurve, core/model/descent_refiner.hpp) of the |yaw| nearest
// `viewYawDeg`'s (a check's photoFitCurves); null when there are none.
const PhotoFitCurve* nearestPhotoFitCurve(const std::vector<PhotoFitCurve>& curves,
                                          double viewYawDeg);

// The probability that a photo's fit is right by `curve`, from its check probability
// `checkProbability` (returned as it is when not finite) and, for a curve with an image term, the
// fit's photoFitFeatures (core/refine/view_check.hpp): 0 when they could not be read.
double photoFitProbability(const PhotoFitCurve& curve, double checkProbability,
                           const Eigen::VectorXf& imageFeatures = {});

// The probability `check` gives to `features` (as descentFeatures gives them).
double checkProbability(const DescentCheck& check, const Eigen::VectorXf& features);

// A check from labelled features (features x samples, `right` per sample): the ridge regression of
// +-1 labels on the `learn` samples, its score turned into a probability by a logistic curve
// fitted on the `calibrate` samples. The refiner's check and the views' checks
// (core/refine/view_check.hpp) are learnt by it. InputError when either list lacks a class.
DescentCheck learnLinearCheck(const Eigen::MatrixXf& features,
                              const std::vector<unsigned char>& right,
                              const std::vector<int>& learn, const std::vector<int>& calibrate,
                              double ridge, double window,
                              const LogisticFitSettings& curveSettings = {});

struct DescentCheckSettings {
  double window = 0.6;  // feature window, eye distances of the mean shape
  // Starts per photo, alternately near the truth (the refiner's own training misplacement) and
  // far from it; each is refined by the whole cascade before its features are taken.
  int startsPerPhoto = 6;
  StartPerturbation nearStart;
  StartPerturbation farStart{0.45, 0.5, 0.3, 0.05};
  // A refined start is wrong when its mean point error exceeds this share of the eye distance
  // (the line the confidence's ROC draws, docs/real-faces.md).
  double wrongAbove = 0.15;
  double ridge = 0.2;
  // Every calibrationEvery-th pair of faces (a photo and its mirror image) is kept out of the
  // classifier and fits the logistic curve instead.
  int calibrationEvery = 5;
  std::uint64_t seed = 1;
  int threads = 0;
};

// Learns the check of `refiner` (trained, with stages) from `photos`. The result does not depend
// on the thread count. InputError when there are too few photos to learn and calibrate from (at
// least 2 * calibrationEvery) or when one class is missing; Cancelled when `cancel` fires.
DescentCheck trainDescentCheck(const std::vector<DescentPhoto>& photos,
                               const DescentRefiner& refiner, const DescentCheckSettings& settings,
                               const CancelToken* cancel = nullptr);

}  // namespace clm3d
