#include "core/refine/descent_check.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <utility>

#include "core/common/error.hpp"
#include "core/common/logistic_curve.hpp"
#include "core/common/parallel_for.hpp"
#include "core/geometry/similarity2.hpp"
#include "core/refine/detail/descent_features.hpp"
#include "core/refine/detail/ridge_regression.hpp"

namespace clm3d {

namespace {

Eigen::VectorXf featuresAt(const DescentRefiner& refiner, const cv::Mat& grey,
                           const Eigen::Matrix2Xd& points, double window) {
  const Similarity2 frame = alignSimilarity2(refiner.meanShape, points);
  return descentFeatures(grey, frame, frame.inverse(points), window);
}

}  // namespace

double checkInRegion(const DescentRefiner& refiner, const cv::Mat& regionGrey,
                     const Eigen::Matrix2Xd& points) {
  const DescentCheck& check = refiner.check;
  if (check.empty() || !points.allFinite()) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::VectorXf features = featuresAt(refiner, regionGrey, points, check.window);
  return checkProbability(check, features);
}

const PhotoFitCurve* nearestPhotoFitCurve(const std::vector<PhotoFitCurve>& curves,
                                          double viewYawDeg) {
  const double yaw = std::abs(viewYawDeg);
  const PhotoFitCurve* nearest = nullptr;
  for (const PhotoFitCurve& curve : curves) {
    if (nearest == nullptr ||
        std::abs(curve.viewYawDeg - yaw) < std::abs(nearest->viewYawDeg - yaw))
      nearest = &curve;
  }
  return nearest;
}

double photoFitProbability(const PhotoFitCurve& curve, double checkProbability,
                           const Eigen::VectorXf& imageFeatures) {
  if (!std::isfinite(checkProbability)) return checkProbability;
  double score = curve.slope * logOdds(checkProbability) + curve.offset;
  if (curve.hasImageTerm()) {
    // Points the features cannot be read at (not finite, an empty box) are not on a face.
    if (imageFeatures.size() != curve.imageWeights.size()) return 0.0;
    score += curve.imageWeights.dot(imageFeatures - curve.imageMean);
  }
  return LogisticCurve{}(score);
}

double checkProbability(const DescentCheck& check, const Eigen::VectorXf& features) {
  const double score = check.weights.dot(features - check.featureMean) + check.bias;
  return LogisticCurve{check.slope, check.offset}(score);
}

DescentCheck learnLinearCheck(const Eigen::MatrixXf& features,
                              const std::vector<unsigned char>& right,
                              const std::vector<int>& learn, const std::vector<int>& calibrate,
                              double ridge, double window,
                              const LogisticFitSettings& curveSettings) {
  const auto hasBoth = [&](const std::vector<int>& samples) {
    int count = 0;
    for (int s : samples) count += right[static_cast<std::size_t>(s)] != 0;
    return count > 0 && count < static_cast<int>(samples.size());
  };
  if (!hasBoth(learn) || !hasBoth(calibrate))
    throw InputError("check: the labelled samples were all right or all wrong");
  const Eigen::Index d = features.rows();
  DescentCheck check;
  check.window = window;
  Eigen::MatrixXf learnFeatures(d, static_cast<Eigen::Index>(learn.size()));
  Eigen::MatrixXf targets(1, static_cast<Eigen::Index>(learn.size()));
  for (std::size_t i = 0; i < learn.size(); ++i) {
    learnFeatures.col(static_cast<Eigen::Index>(i)) = features.col(learn[i]);
    targets(0, static_cast<Eigen::Index>(i)) =
        right[static_cast<std::size_t>(learn[i])] ? 1.f : -1.f;
  }
  check.featureMean = learnFeatures.rowwise().mean();
  learnFeatures.colwise() -= check.featureMean;
  const float meanTarget = targets.mean();
  targets.array() -= meanTarget;
  check.weights = ridgeRegression(learnFeatures, targets, ridge).row(0).transpose();
  check.bias = meanTarget;

  std::vector<double> scores;
  std::vector<bool> labels;
  for (int s : calibrate) {
    scores.push_back(check.weights.dot(features.col(s) - check.featureMean) + check.bias);
    labels.push_back(right[static_cast<std::size_t>(s)] != 0);
  }
  const LogisticCurve curve = fitLogisticCurve(scores, labels, curveSettings);
  check.slope = curve.slope;
  check.offset = curve.offset;
  return check;
}

DescentCheck trainDescentCheck(const std::vector<DescentPhoto>& photos,
                               const DescentRefiner& refiner, const DescentCheckSettings& settings,
                               const CancelToken* cancel) {
  if (refiner.empty()) throw InputError("refiner check: the refiner has no stages");
  const int every = std::max(2, settings.calibrationEvery);
  if (photos.size() < 2 * static_cast<std::size_t>(every))
    throw InputError("refiner check: too few photos to learn and calibrate from");
  if (settings.startsPerPhoto < 2) throw InputError("refiner check: need 2 starts per photo");
  const int perPhoto = settings.startsPerPhoto;
  const int m = static_cast<int>(photos.size()) * perPhoto;
  const Eigen::Index d =
      static_cast<Eigen::Index>(refiner.landmarks.size()) * kDescentFeaturesPerPoint;
  Eigen::MatrixXf features(d, m);
  // One byte per start: the photos' workers write neighbouring entries (a packed vector<bool> would
  // share words between them, a data race that made the check differ from run to run).
  std::vector<unsigned char> right(static_cast<std::size_t>(m));
  parallelFor(
      static_cast<int>(photos.size()), settings.threads,
      [&](int p) {
        const DescentPhoto& photo = photos[static_cast<std::size_t>(p)];
        const Eigen::Matrix2Xd& truth = photo.truth;
        const double eyeDistance =
            (truth.col(refiner.leftEye) - truth.col(refiner.rightEye)).norm();
        std::mt19937_64 random(settings.seed * 7919u + static_cast<std::uint64_t>(p));
        for (int k = 0; k < perPhoto; ++k) {
          const StartPerturbation& how = k % 2 == 0 ? settings.nearStart : settings.farStart;
          const Eigen::Matrix2Xd start = perturbedPoints(truth, eyeDistance, how, random);
          const Eigen::Matrix2Xd refined = refineInRegion(refiner, photo.region.grey, start);
          const int s = p * perPhoto + k;
          features.col(s) = featuresAt(refiner, photo.region.grey, refined, settings.window);
          right[static_cast<std::size_t>(s)] =
              meanPointError(refined, truth, eyeDistance) <= settings.wrongAbove;
        }
      },
      cancel);

  // Learn on most pairs of faces, calibrate on the rest.
  const auto calibrates = [&](int s) { return (s / perPhoto / 2) % every == every - 1; };
  std::vector<int> learn, calibrate;
  for (int s = 0; s < m; ++s) (calibrates(s) ? calibrate : learn).push_back(s);
  return learnLinearCheck(features, right, learn, calibrate, settings.ridge, settings.window);
}

}  // namespace clm3d
