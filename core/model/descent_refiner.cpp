#include "core/model/descent_refiner.hpp"

#include <cmath>
#include <string>

#include "core/common/error.hpp"

namespace clm3d {

void DescentRefiner::validate(int schemeSize) const {
  if (stages.empty()) {
    if (!check.empty()) throw Error("a check without refiner stages");
    return;
  }
  const auto n = static_cast<Eigen::Index>(landmarks.size());
  const auto fail = [](const std::string& what) { throw Error(what); };
  if (n < 3) fail("needs at least 3 landmarks");
  for (int l : landmarks) {
    if (l < 0 || l >= schemeSize) fail("landmark index " + std::to_string(l) + " out of range");
  }
  if (leftEye < 0 || leftEye >= n || rightEye < 0 || rightEye >= n || leftEye == rightEye)
    fail("eye positions out of range");
  if (meanShape.cols() != n || !meanShape.allFinite()) fail("mean shape size or values");
  const Eigen::Index d = n * kDescentFeaturesPerPoint;
  for (std::size_t s = 0; s < stages.size(); ++s) {
    const DescentStage& stage = stages[s];
    const std::string where = "stages[" + std::to_string(s) + "]";
    if (!(stage.window > 0.0 && stage.window <= 4.0)) fail(where + ".window must be in (0, 4]");
    if (stage.featureMean.size() != d || stage.weights.rows() != 2 * n ||
        stage.weights.cols() != d || stage.bias.size() != 2 * n)
      fail(where + ": array sizes do not match " + std::to_string(n) + " landmarks");
    if (!stage.featureMean.allFinite() || !stage.weights.allFinite() || !stage.bias.allFinite())
      fail(where + ": values not finite");
    if (stage.shapeWeights.size() > 0) {
      if (stage.shapeWeights.rows() != 2 * n || stage.shapeWeights.cols() != 2 * n)
        fail(where + ".shapeWeights must be " + std::to_string(2 * n) + " x " +
             std::to_string(2 * n));
      if (!stage.shapeWeights.allFinite()) fail(where + ".shapeWeights: values not finite");
    }
    if ((stage.shapeWeights.size() > 0) != hasShapeWeights())
      fail(where + ": shape weights in some stages and not in others");
  }
  if (!check.empty()) check.validate(n);
}

void DescentCheck::validate(Eigen::Index points) const {
  const Eigen::Index d = points * kDescentFeaturesPerPoint;
  if (!(window > 0.0 && window <= 4.0)) throw Error("check.window must be in (0, 4]");
  if (featureMean.size() != d || weights.size() != d)
    throw Error("check: array sizes do not match " + std::to_string(points) + " landmarks");
  if (!featureMean.allFinite() || !weights.allFinite() || !std::isfinite(bias) ||
      !std::isfinite(slope) || !std::isfinite(offset))
    throw Error("check: values not finite");
  for (const PhotoFitCurve& curve : photoFitCurves) {
    if (!(curve.viewYawDeg >= 0.0 && curve.viewYawDeg <= 180.0) || !std::isfinite(curve.slope) ||
        !std::isfinite(curve.offset))
      throw Error("check.photoFitCurves: a view's |yaw| in [0, 180] and finite curves");
    if (curve.imageMean.size() != curve.imageWeights.size() ||
        curve.imageWeights.size() % kDescentFeaturesPerPoint != 0 || !curve.imageMean.allFinite() ||
        !curve.imageWeights.allFinite())
      throw Error(
          "check.photoFitCurves: an image term's mean and weights must be finite, of one "
          "size, a whole number of landmarks' features");
  }
}

}  // namespace clm3d
