// The photo-fit judge's learning (learnPhotoFitJudge): where the image features tell right fits
// from wrong ones and the check's log-odds do not, the learnt curve ranks new fits by their
// features; where only the log-odds carry the label, the features' weights stay small and the curve
// follows the log-odds.
#include "core/eval/detail/photo_fit_judge.hpp"

#include <gtest/gtest.h>

#include <random>

#include "core/eval/detail/confidence_roc.hpp"
#include "core/refine/descent_check.hpp"

namespace clm3d {
namespace {

constexpr int kFeatures = 2 * kDescentFeaturesPerPoint;

// n fits: features N(0, 1) with the label's sign on feature 7 times `imageSignal`, log-odds
// N(0, 1) plus the label's sign times `checkSignal`; right with probability 1/2.
PhotoFitSample sampleOf(int n, double imageSignal, double checkSignal, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  PhotoFitSample sample;
  sample.features.resize(n, kFeatures);
  for (int i = 0; i < n; ++i) {
    const bool right = random() % 2 == 0;
    const double sign = right ? 1.0 : -1.0;
    for (int j = 0; j < kFeatures; ++j) sample.features(i, j) = static_cast<float>(normal(random));
    sample.features(i, 7) += static_cast<float>(imageSignal * sign);
    sample.logOdds.push_back(normal(random) + checkSignal * sign);
    sample.right.push_back(right);
  }
  return sample;
}

double rocOf(const PhotoFitCurve& curve, const PhotoFitSample& sample) {
  std::vector<ScoredFit> fits;
  for (Eigen::Index i = 0; i < sample.features.rows(); ++i) {
    const double checkProbability =
        1.0 / (1.0 + std::exp(-sample.logOdds[static_cast<std::size_t>(i)]));
    const Eigen::VectorXf features = sample.features.row(i).transpose();
    fits.push_back({photoFitProbability(curve, checkProbability, features),
                    sample.right[static_cast<std::size_t>(i)] ? 0.0 : 1.0});
  }
  return confidenceRoc(fits, 0.5).auc;
}

TEST(PhotoFitJudge, LearnsWhatTheImageSaysAndTheCheckDoesNot) {
  const PhotoFitCurve curve = learnPhotoFitJudge(60.0, sampleOf(300, 2.0, 0.0, 1));
  EXPECT_EQ(curve.viewYawDeg, 60.0);
  ASSERT_EQ(curve.imageWeights.size(), kFeatures);
  ASSERT_EQ(curve.imageMean.size(), kFeatures);
  const PhotoFitSample fresh = sampleOf(400, 2.0, 0.0, 2);
  EXPECT_GT(rocOf(curve, fresh), 0.9);
  const PhotoFitCurve checkOnly{60.0, 1.0, 0.0, {}, {}};
  EXPECT_NEAR(rocOf(checkOnly, fresh), 0.5, 0.08) << "the log-odds carry nothing here";
  // The weight on the informative feature is the largest.
  Eigen::Index largest = 0;
  curve.imageWeights.cwiseAbs().maxCoeff(&largest);
  EXPECT_EQ(largest, 7);
}

TEST(PhotoFitJudge, FollowsTheCheckWhenTheImageSaysNothing) {
  const PhotoFitCurve curve = learnPhotoFitJudge(0.0, sampleOf(300, 0.0, 1.5, 3));
  const PhotoFitSample fresh = sampleOf(400, 0.0, 1.5, 4);
  const PhotoFitCurve checkOnly{0.0, 1.0, 0.0, {}, {}};
  EXPECT_FALSE(curve.hasImageTerm()) << "cross-validation shows no gain from the image";
  EXPECT_GT(curve.slope, 0.5);
  EXPECT_GT(rocOf(curve, fresh), rocOf(checkOnly, fresh) - 0.03);
}

}  // namespace
}  // namespace clm3d
