// Tests of the patch-expert trainer: on regions of a textured pattern with a distinctive corner at
// the centre (random texture, brightness and contrast per region) the expert's response map peaks
// at the centre, is above one half there and below it three or more pixels away; training is
// deterministic; bad input is refused.
#include "core/train/detail/expert_training.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <opencv2/core.hpp>

#include "core/common/error.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/fit/response_map.hpp"

namespace clm3d {
namespace {

constexpr int kPatch = 12;
constexpr int kRadius = 5;
constexpr int kRegion = kPatch + 2 * kRadius;

// A dark quarter-plane whose corner is at the region's centre (a mouth or eye corner), with
// noise, a random brightness and contrast, and the corner up to 0.3 px off.
cv::Mat cornerRegion(SplitMixRandom& random, bool turned = false) {
  cv::Mat region(kRegion, kRegion, CV_32FC1);
  const double centre = (kRegion - 1) / 2.0;
  const double offX = random.symmetric(0.3);
  const double offY = random.symmetric(0.3);
  const double brightness = random.uniform(0.2, 0.6);
  const double contrast = random.uniform(0.2, 0.4);
  for (int r = 0; r < kRegion; ++r) {
    for (int c = 0; c < kRegion; ++c) {
      const double x = (turned ? -1.0 : 1.0) * (c - centre - offX);
      const double y = (turned ? -1.0 : 1.0) * (r - centre - offY);
      // Smooth edges (logistic of the distance to each half-plane).
      const double inside = 1.0 / (1.0 + std::exp(-2.0 * x)) * 1.0 / (1.0 + std::exp(-2.0 * y));
      region.at<float>(r, c) =
          static_cast<float>(brightness + contrast * (1.0 - inside) + random.symmetric(0.03));
    }
  }
  return region;
}

// `count` regions; with `mixed`, every other one has its dark quarter on the other side.
Eigen::MatrixXf trainingRegions(int count, std::uint64_t seed, bool mixed = false) {
  SplitMixRandom random(seed);
  Eigen::MatrixXf regions(kRegion * kRegion, count);
  for (int k = 0; k < count; ++k) {
    const cv::Mat region = cornerRegion(random, mixed && k % 2 == 1);
    for (int r = 0; r < kRegion; ++r) {
      for (int c = 0; c < kRegion; ++c) regions(r * kRegion + c, k) = region.at<float>(r, c);
    }
  }
  return regions;
}

ExpertTrainingSettings settings() {
  ExpertTrainingSettings s;
  s.patchSize = kPatch;
  s.radius = kRadius;
  return s;
}

TEST(ExpertTraining, ResponsePeaksAtTheTrainedPoint) {
  const PatchExpert expert = trainPatchExpert(trainingRegions(60, 1), settings());
  ASSERT_EQ(expert.weights.size(), kPatch * kPatch);
  EXPECT_NEAR(expert.weights.mean(), 0.0f, 1e-6f);
  SplitMixRandom random(99);  // unseen regions
  int peaked = 0;
  for (int k = 0; k < 20; ++k) {
    const cv::Mat region = cornerRegion(random);
    cv::Mat response;
    expertResponse(region, expert, kPatch, response);
    ASSERT_EQ(response.rows, 2 * kRadius + 1);
    cv::Point best;
    cv::minMaxLoc(response, nullptr, nullptr, nullptr, &best);
    if (best.x == kRadius && best.y == kRadius) ++peaked;
    EXPECT_GT(response.at<float>(kRadius, kRadius), 0.5f);
    for (int r = 0; r < response.rows; ++r) {
      for (int c = 0; c < response.cols; ++c) {
        if (std::max(std::abs(r - kRadius), std::abs(c - kRadius)) >= 3) {
          EXPECT_LT(response.at<float>(r, c), 0.5f) << "at " << c - kRadius << ", " << r - kRadius;
        }
      }
    }
  }
  EXPECT_GE(peaked, 18);
}

TEST(ExpertTraining, Deterministic) {
  const Eigen::MatrixXf regions = trainingRegions(30, 2);
  const PatchExpert a = trainPatchExpert(regions, settings());
  const PatchExpert b = trainPatchExpert(regions, settings());
  EXPECT_EQ(a.weights, b.weights);
  EXPECT_EQ(a.bias, b.bias);
  EXPECT_EQ(a.alpha, b.alpha);
}

// The share of unseen regions (both kinds when `mixed`) whose response map peaks at the centre.
double peakedShare(const PatchExpert& expert, bool mixed) {
  SplitMixRandom random(77);
  int peaked = 0;
  constexpr int kCount = 40;
  for (int k = 0; k < kCount; ++k) {
    const cv::Mat region = cornerRegion(random, mixed && k % 2 == 1);
    cv::Mat response;
    expertResponse(region, expert, kPatch, response);
    cv::Point best;
    cv::minMaxLoc(response, nullptr, nullptr, nullptr, &best);
    if (best.x == kRadius && best.y == kRadius) ++peaked;
  }
  return static_cast<double>(peaked) / kCount;
}

// A landmark that looks one of two ways (the dark quarter on either side of the corner): a neural
// field of four units beats the linear expert on the held-out regions, so it is kept, and finds
// the corner in unseen regions of both kinds at least as often. Training stays deterministic.
TEST(ExpertTraining, NeuralFieldLearnsTwoAppearances) {
  const Eigen::MatrixXf regions = trainingRegions(120, 4, true);
  const PatchExpert linear = trainPatchExpert(regions, settings());
  ExpertTrainingSettings neural = settings();
  neural.units = 4;
  const PatchExpert field = trainPatchExpert(regions, neural);
  ASSERT_EQ(field.units(), 4);
  // Kept: a linear expert that won on the held-out regions would come back with silent units.
  EXPECT_GT(field.alpha.tail(3).cwiseAbs().sum(), 0.0f);
  EXPECT_EQ(field.bias.size(), 4);
  EXPECT_EQ(field.alpha.size(), 4);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(field.weights.col(k).mean(), 0.0f, 1e-5f);
  const double linearShare = peakedShare(linear, true);
  const double fieldShare = peakedShare(field, true);
  std::cout << "[ peaked at the corner: linear " << linearShare << ", neural field " << fieldShare
            << " ]\n";
  EXPECT_GE(fieldShare, linearShare);
  EXPECT_GE(fieldShare, 0.8);
  const PatchExpert again = trainPatchExpert(regions, neural);
  EXPECT_EQ(again.weights, field.weights);
  EXPECT_EQ(again.alpha, field.alpha);
}

TEST(ExpertTraining, RefusesBadInput) {
  EXPECT_THROW(trainPatchExpert(Eigen::MatrixXf(kRegion * kRegion, 0), settings()), Error);
  EXPECT_THROW(trainPatchExpert(Eigen::MatrixXf::Zero(10, 3), settings()), Error);
  ExpertTrainingSettings noUnits = settings();
  noUnits.units = 0;
  EXPECT_THROW(trainPatchExpert(trainingRegions(5, 1), noUnits), Error);
}

// The score map of sampleRegion + expertScores equals the expert applied to each normalised
// window, so training (windows of stored regions) and search (matchTemplate) agree.
TEST(ExpertTraining, ScoresMatchTheNormalisedWindows) {
  const PatchExpert expert = trainPatchExpert(trainingRegions(20, 3), settings());
  SplitMixRandom random(5);
  const cv::Mat region = cornerRegion(random);
  cv::Mat scores;
  expertScores(region, expert, kPatch, scores);
  for (int dy = -kRadius; dy <= kRadius; dy += 3) {
    for (int dx = -kRadius; dx <= kRadius; dx += 3) {
      Eigen::VectorXf window(kPatch * kPatch);
      for (int r = 0; r < kPatch; ++r) {
        for (int c = 0; c < kPatch; ++c) {
          window[r * kPatch + c] = region.at<float>(kRadius + dy + r, kRadius + dx + c);
        }
      }
      const float mean = window.mean();
      const float sd = std::sqrt((window.array() - mean).square().mean());
      const float expected = expert.weights.col(0).dot((window.array() - mean).matrix() / sd);
      EXPECT_NEAR(scores.at<float>(dy + kRadius, dx + kRadius), expected,
                  1e-3f * (1.0f + std::abs(expected)));
    }
  }
}

}  // namespace
}  // namespace clm3d
