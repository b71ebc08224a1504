// Patch normalisation, patch PCA reconstruction, and mirrored views.
#include "core/model/texture_model.hpp"

#include <gtest/gtest.h>

#include <random>

#include "core/common/error.hpp"
#include "tests/support/tiny_model.hpp"

namespace clm3d {
namespace {

TEST(NormalisePatch, GivesZeroMeanUnitVariance) {
  Eigen::VectorXf patch(9);
  patch << 10, 20, 30, 40, 50, 60, 70, 80, 250;
  normalisePatch(patch);
  EXPECT_NEAR(patch.mean(), 0.0f, 1e-6f);
  EXPECT_NEAR(patch.squaredNorm() / 9.0f, 1.0f, 1e-5f);
  // Order is kept: the brightest pixel stays the brightest.
  Eigen::Index brightest = 0;
  patch.maxCoeff(&brightest);
  EXPECT_EQ(brightest, 8);
}

TEST(NormalisePatch, ConstantPatchBecomesZeros) {
  Eigen::VectorXf patch = Eigen::VectorXf::Constant(16, 128.0f);
  normalisePatch(patch);
  EXPECT_EQ(patch, Eigen::VectorXf::Zero(16));
  Eigen::VectorXf empty;
  normalisePatch(empty);
  EXPECT_EQ(empty.size(), 0);
}

TEST(NormalisePatch, IsInvariantToBrightnessAndContrast) {
  Eigen::VectorXf a(4);
  a << 1, 5, 2, 9;
  Eigen::VectorXf b = (a.array() * 3.5f + 40.0f).matrix();
  normalisePatch(a);
  normalisePatch(b);
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-5f);
}

TEST(PatchModel, PatchReconstructedFromItsOwnPcaModelMatches) {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> uniform(0.0f, 255.0f);
  const int size = 20, landmarks = 3, samples = 12;
  Eigen::MatrixXf data(landmarks * size * size, samples);
  for (Eigen::Index i = 0; i < data.size(); ++i) data.data()[i] = uniform(random);
  for (int s = 0; s < samples; ++s) {
    for (int e = 0; e < landmarks; ++e) normalisePatch(data.col(s).segment(e * 400, 400));
  }
  const PcaModel pca = fitPca(data, 1.0);
  EXPECT_EQ(pca.modeCount(), samples - 1);
  for (int s = 0; s < samples; ++s) {
    const Eigen::VectorXf reconstructed = pca.reconstruct(pca.project(data.col(s)));
    EXPECT_LT((reconstructed - data.col(s)).cwiseAbs().maxCoeff(), 1e-4f) << "sample " << s;
  }
  // Fewer modes: a training patch is approximated, not reproduced.
  const PcaModel few = fitPca(data, 0.5);
  EXPECT_LT(few.modeCount(), pca.modeCount());
  EXPECT_GT((few.reconstruct(few.project(data.col(0))) - data.col(0)).norm(), 1e-2f);
}

TEST(PatchModel, EntryOfFindsLandmarks) {
  PatchModel patch;
  patch.landmarks = {0, 3, 4};
  EXPECT_EQ(patch.entryOf(3), 1);
  EXPECT_EQ(patch.entryOf(2), -1);
  EXPECT_EQ(patch.entryOf(7), -1);
}

TEST(FlipPatch, FlipsLeftRight) {
  Eigen::VectorXf patch(6);
  patch << 1, 2, 3, 4, 5, 6;
  EXPECT_THROW(flipPatch(patch, 2), Error);
  Eigen::VectorXf square(4);
  square << 1, 2, 3, 4;
  Eigen::VectorXf expected(4);
  expected << 2, 1, 4, 3;
  EXPECT_EQ(flipPatch(square, 2), expected);
}

TEST(MirrorView, MirroredPatchIsTheFlippedSourcePatch) {
  const ClmModel model = test::makeTinyModel();
  const Scheme scheme = model.scheme();
  const ViewModel& left = model.views[0];  // yaw -30, hides the right eye (2)
  const ViewModel right = mirrorView(left, scheme);
  EXPECT_EQ(right.yawDeg, 30.0);
  EXPECT_EQ(right.pitchDeg, left.pitchDeg);
  EXPECT_TRUE(right.mirrored);
  EXPECT_EQ(right.visible, (std::vector<bool>{true, false, true, true, true}));
  ASSERT_EQ(right.scales.size(), left.scales.size());
  for (std::size_t s = 0; s < left.scales.size(); ++s) {
    const PatchModel& source = left.scales[s];
    const PatchModel& mirrored = right.scales[s];
    EXPECT_EQ(mirrored.landmarks, (std::vector<int>{0, 2, 3, 4}));
    const int pixels = source.patchPixels();
    for (std::size_t e = 0; e < mirrored.landmarks.size(); ++e) {
      const int from = source.entryOf(scheme.mirrorOf(mirrored.landmarks[e]));
      ASSERT_GE(from, 0);
      const auto entry = static_cast<int>(e);
      EXPECT_EQ(mirrored.pca.mean.segment(mirrored.offsetOf(entry), pixels),
                flipPatch(source.pca.mean.segment(source.offsetOf(from), pixels), 4));
      EXPECT_EQ(mirrored.alpha[e], flipPatch(source.alpha[static_cast<std::size_t>(from)], 4));
      for (int k = 0; k < source.pca.modeCount(); ++k) {
        EXPECT_EQ(
            mirrored.pca.components.col(k).segment(mirrored.offsetOf(entry), pixels),
            flipPatch(source.pca.components.col(k).segment(source.offsetOf(from), pixels), 4));
      }
    }
    EXPECT_EQ(mirrored.pca.variances, source.pca.variances);
  }
}

TEST(MirrorView, MirroringTwiceGivesTheOriginal) {
  const ClmModel model = test::makeTinyModel();
  const Scheme scheme = model.scheme();
  for (const ViewModel& view : model.views) {
    const ViewModel twice = mirrorView(mirrorView(view, scheme), scheme);
    EXPECT_EQ(twice.yawDeg, view.yawDeg);
    EXPECT_EQ(twice.mirrored, view.mirrored);
    EXPECT_EQ(twice.visible, view.visible);
    for (std::size_t s = 0; s < view.scales.size(); ++s) {
      EXPECT_EQ(twice.scales[s].landmarks, view.scales[s].landmarks);
      EXPECT_EQ(twice.scales[s].pca.mean, view.scales[s].pca.mean);
      EXPECT_EQ(twice.scales[s].pca.components, view.scales[s].pca.components);
      EXPECT_EQ(twice.scales[s].alpha, view.scales[s].alpha);
    }
  }
}

TEST(MirrorView, RejectsAViewOfAnotherScheme) {
  const ClmModel model = test::makeTinyModel();
  EXPECT_THROW(mirrorView(model.views[0], Scheme::thesis25()), Error);
}

}  // namespace
}  // namespace clm3d
