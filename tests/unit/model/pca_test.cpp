// fitPca: exact reconstruction of low-rank data, orthonormal modes, the variance-kept rule, and
// the Gram-matrix path agreeing with the covariance path.
#include "core/model/pca.hpp"

#include <gtest/gtest.h>

#include <Eigen/QR>
#include <random>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

Eigen::MatrixXf randomMatrix(Eigen::Index rows, Eigen::Index cols, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  Eigen::MatrixXf m(rows, cols);
  for (Eigen::Index i = 0; i < m.size(); ++i) m.data()[i] = normal(random);
  return m;
}

// D x N samples = offset + basis (D x rank) * coefficients.
Eigen::MatrixXf lowRank(Eigen::Index d, Eigen::Index n, Eigen::Index rank, unsigned seed) {
  const Eigen::MatrixXf basis = randomMatrix(d, rank, seed);
  const Eigen::MatrixXf coefficients = randomMatrix(rank, n, seed + 1) * 3.0f;
  const Eigen::VectorXf offset = randomMatrix(d, 1, seed + 2).col(0) * 5.0f;
  return (basis * coefficients).colwise() + offset;
}

TEST(Pca, ReconstructsLowRankTrainingSamplesExactly) {
  const Eigen::MatrixXf samples = lowRank(40, 12, 3, 7);  // N < D: Gram path
  const PcaModel model = fitPca(samples, 1.0);
  EXPECT_EQ(model.dimension(), 40);
  EXPECT_EQ(model.modeCount(), 3);
  const Eigen::MatrixXf gram = model.components.transpose() * model.components;
  EXPECT_TRUE(gram.isApprox(Eigen::MatrixXf::Identity(3, 3), 1e-5f)) << gram;
  for (Eigen::Index s = 0; s < samples.cols(); ++s) {
    const Eigen::VectorXf b = model.project(samples.col(s));
    EXPECT_LT((model.reconstruct(b) - samples.col(s)).cwiseAbs().maxCoeff(), 1e-4f);
  }
  for (Eigen::Index k = 1; k < model.variances.size(); ++k) {
    EXPECT_GE(model.variances[k - 1], model.variances[k]);
  }
}

TEST(Pca, KeepsTheFewestModesExplainingTheVarianceShare) {
  // Samples +-a_k along three orthogonal axes: variances 100, 10, 1 (total 111).
  const Eigen::MatrixXf axes =
      randomMatrix(6, 3, 3).householderQr().householderQ() * Eigen::MatrixXf::Identity(6, 3);
  Eigen::MatrixXf samples(6, 6);
  const float spreads[3] = {10.0f, std::sqrt(10.0f), 1.0f};
  for (int k = 0; k < 3; ++k) {
    samples.col(2 * k) = spreads[k] * std::sqrt(3.0f) * axes.col(k);
    samples.col(2 * k + 1) = -spreads[k] * std::sqrt(3.0f) * axes.col(k);
  }
  EXPECT_EQ(fitPca(samples, 0.90).modeCount(), 1);  // 100 / 111 = 0.901
  EXPECT_EQ(fitPca(samples, 0.95).modeCount(), 2);  // 110 / 111 = 0.991
  EXPECT_EQ(fitPca(samples, 0.995).modeCount(), 3);
  EXPECT_EQ(fitPca(samples, 1.0).modeCount(), 3);  // never keeps the zero-variance directions
  EXPECT_EQ(fitPca(samples, 1.0, 2).modeCount(), 2);
  const PcaModel model = fitPca(samples, 1.0);
  EXPECT_NEAR(model.variances[0], 100.0f, 1e-3f);
  EXPECT_NEAR(model.variances[1], 10.0f, 1e-4f);
  EXPECT_NEAR(model.variances[2], 1.0f, 1e-5f);
  EXPECT_NEAR(std::abs(model.components.col(0).dot(axes.col(0))), 1.0f, 1e-5f);
}

TEST(Pca, GramPathEqualsCovariancePath) {
  const Eigen::MatrixXf samples = lowRank(9, 7, 4, 11);  // 7 < 9: Gram path
  Eigen::MatrixXf doubled(9, 14);                        // same covariance, 14 >= 9: direct path
  doubled << samples, samples;
  const PcaModel gram = fitPca(samples, 1.0);
  const PcaModel direct = fitPca(doubled, 1.0);
  ASSERT_EQ(gram.modeCount(), 4);
  ASSERT_EQ(direct.modeCount(), 4);
  EXPECT_TRUE(gram.mean.isApprox(direct.mean, 1e-6f));
  EXPECT_TRUE(gram.variances.isApprox(direct.variances, 1e-4f));
  for (int k = 0; k < 4; ++k) {
    // Signs are fixed the same way on both paths, so the columns agree without sign juggling.
    EXPECT_LT((gram.components.col(k) - direct.components.col(k)).cwiseAbs().maxCoeff(), 1e-4f)
        << "mode " << k;
  }
}

TEST(Pca, FixesSignsSoTheLargestEntryIsPositive) {
  const PcaModel model = fitPca(lowRank(10, 5, 2, 5), 1.0);
  for (int k = 0; k < model.modeCount(); ++k) {
    Eigen::Index index = 0;
    model.components.col(k).cwiseAbs().maxCoeff(&index);
    EXPECT_GT(model.components(index, k), 0.0f);
  }
  EXPECT_EQ(fitPca(lowRank(10, 5, 2, 5), 1.0).components, model.components);
}

TEST(Pca, ConstantSamplesGiveNoModes) {
  const PcaModel model = fitPca(Eigen::MatrixXf::Constant(5, 4, 2.0f), 0.98);
  EXPECT_EQ(model.modeCount(), 0);
  EXPECT_EQ(model.reconstruct(Eigen::VectorXf()), Eigen::VectorXf::Constant(5, 2.0f));
}

TEST(Pca, RejectsBadInput) {
  EXPECT_THROW(fitPca(Eigen::MatrixXf(0, 0), 0.98), Error);
  Eigen::MatrixXf withNan = Eigen::MatrixXf::Ones(3, 3);
  withNan(1, 1) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(fitPca(withNan, 0.98), Error);
  EXPECT_THROW(fitPca(Eigen::MatrixXf::Ones(3, 3), 0.0), Error);
  EXPECT_THROW(fitPca(Eigen::MatrixXf::Ones(3, 3), 1.5), Error);
  const PcaModel model = fitPca(lowRank(6, 4, 2, 1), 1.0);
  EXPECT_THROW(model.project(Eigen::VectorXf::Zero(5)), Error);
  EXPECT_THROW(model.reconstruct(Eigen::VectorXf::Zero(5)), Error);
}

}  // namespace
}  // namespace clm3d
