#include "core/train/expert_training.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/model/texture_model.hpp"

namespace clm3d {
namespace {

struct Offset {
  int dx, dy;
};

// Copies the patchSize window of a row-major region displaced by (dx, dy) from its centre.
void windowAt(const float* region, int regionSize, int patchSize, int radius, Offset offset,
              Eigen::Ref<Eigen::VectorXf> out) {
  const int top = radius + offset.dy;
  const int left = radius + offset.dx;
  for (int r = 0; r < patchSize; ++r) {
    const float* row = region + static_cast<std::ptrdiff_t>(top + r) * regionSize + left;
    for (int c = 0; c < patchSize; ++c) out[r * patchSize + c] = row[c];
  }
}

// The displacements taken from region `column`: the true position, its 8 neighbours, and
// negatives drawn from the ring 2..radius (Chebyshev distance).
std::vector<Offset> offsetsFor(std::uint64_t seed, Eigen::Index column,
                               const ExpertTrainingSettings& settings) {
  std::vector<Offset> offsets;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) offsets.push_back({dx, dy});
  }
  if (settings.radius < 2) return offsets;
  SplitMixRandom random(mixKey(seed, static_cast<std::uint64_t>(column)));
  for (int k = 0; k < settings.negativesPerRegion; ++k) {
    Offset offset{0, 0};
    while (std::max(std::abs(offset.dx), std::abs(offset.dy)) < 2) {
      offset = {random.integer(-settings.radius, settings.radius),
                random.integer(-settings.radius, settings.radius)};
    }
    offsets.push_back(offset);
  }
  return offsets;
}

double sigmoid(double x) {
  return 1.0 / (1.0 + std::exp(-x));
}

// Logistic regression of labels on one score (gain, bias), Newton's method with a small ridge
// so that separable data does not run off to infinity.
void fitLogistic(const std::vector<double>& scores, const std::vector<int>& labels,
                 PatchExpert& expert) {
  double positives = 0;
  for (const int label : labels) positives += label;
  const double negatives = static_cast<double>(labels.size()) - positives;
  if (positives == 0 || negatives == 0) return;
  const double weightPositive = 0.5 / positives;
  const double weightNegative = 0.5 / negatives;
  double a = 1.0;
  double b = 0.0;
  for (int iteration = 0; iteration < 30; ++iteration) {
    Eigen::Matrix2d hessian = Eigen::Matrix2d::Identity() * 1e-4;
    Eigen::Vector2d gradient(1e-4 * a, 1e-4 * b);
    for (std::size_t i = 0; i < scores.size(); ++i) {
      const double w = labels[i] ? weightPositive : weightNegative;
      const double pr = sigmoid(a * scores[i] + b);
      const Eigen::Vector2d x(scores[i], 1.0);
      gradient += w * (pr - labels[i]) * x;
      hessian += w * pr * (1.0 - pr) * x * x.transpose();
    }
    const Eigen::Vector2d step = hessian.ldlt().solve(gradient);
    if (!step.allFinite()) break;
    a -= step[0];
    b -= step[1];
    if (step.norm() < 1e-6) break;
  }
  expert.gain = static_cast<float>(a);
  expert.bias = static_cast<float>(b);
}

}  // namespace

PatchExpert trainPatchExpert(const Eigen::Ref<const Eigen::MatrixXf>& regions,
                             const ExpertTrainingSettings& settings) {
  const int patch = settings.patchSize;
  const int regionSize = patch + 2 * settings.radius;
  if (patch < 2 || settings.radius < 1) throw Error("expert training: bad patch size or radius");
  if (regions.cols() == 0) throw Error("expert training: no regions");
  if (regions.rows() != Eigen::Index(regionSize) * regionSize) {
    throw Error("expert training: regions of " + std::to_string(regions.rows()) +
                " values, expected " + std::to_string(regionSize * regionSize));
  }
  const int pixels = patch * patch;
  // Gram matrix and right-hand side of the ridge regression, in double, from batches of rows.
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(pixels, pixels);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(pixels);
  Eigen::Index rows = 0;
  constexpr int kBatch = 256;
  Eigen::MatrixXf batch(pixels, kBatch);
  Eigen::VectorXf targets(kBatch);
  int filled = 0;
  const auto flush = [&] {
    if (filled == 0) return;
    const Eigen::MatrixXd block = batch.leftCols(filled).cast<double>();
    gram.selfadjointView<Eigen::Lower>().rankUpdate(block);
    rhs.noalias() += block * targets.head(filled).cast<double>();
    rows += filled;
    filled = 0;
  };
  for (Eigen::Index column = 0; column < regions.cols(); ++column) {
    const float* region = regions.col(column).data();
    for (const Offset offset : offsetsFor(settings.seed, column, settings)) {
      auto x = batch.col(filled);
      windowAt(region, regionSize, patch, settings.radius, offset, x);
      normalisePatch(x);
      const double distance2 = offset.dx * offset.dx + offset.dy * offset.dy;
      targets[filled] = static_cast<float>(std::exp(-0.5 * distance2));
      if (++filled == kBatch) flush();
    }
  }
  flush();
  gram.triangularView<Eigen::StrictlyUpper>() = gram.transpose();
  const double ridge = settings.ridge * std::max(gram.trace() / pixels, 1e-9);
  gram.diagonal().array() += ridge;
  Eigen::VectorXd weights = gram.ldlt().solve(rhs);
  if (!weights.allFinite()) throw Error("expert training: the regression did not solve");
  weights.array() -= weights.mean();  // normalised patches are zero-mean: no effect on scores

  PatchExpert expert;
  expert.weights = weights.cast<float>();
  std::vector<double> scores;
  std::vector<int> labels;
  Eigen::VectorXf x(pixels);
  for (Eigen::Index column = 0; column < regions.cols(); ++column) {
    const float* region = regions.col(column).data();
    for (const Offset offset : offsetsFor(settings.seed, column, settings)) {
      const int chebyshev = std::max(std::abs(offset.dx), std::abs(offset.dy));
      if (chebyshev == 1) continue;  // neither right nor wrong
      windowAt(region, regionSize, patch, settings.radius, offset, x);
      normalisePatch(x);
      scores.push_back(expert.weights.dot(x));
      labels.push_back(chebyshev == 0 ? 1 : 0);
    }
  }
  fitLogistic(scores, labels, expert);
  return expert;
}

}  // namespace clm3d
