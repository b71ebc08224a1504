#include "core/train/detail/expert_training.hpp"

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

// The regression target of a window displaced by `offset`: a Gaussian of the displacement, 1 px SD.
float targetOf(Offset offset) {
  return static_cast<float>(std::exp(-0.5 * (offset.dx * offset.dx + offset.dy * offset.dy)));
}

double sigmoid(double x) {
  return 1.0 / (1.0 + std::exp(-x));
}

// Logistic regression of labels on one score (gain, bias), Newton's method with a small ridge
// so that separable data does not run off to infinity.
Eigen::Vector2d fitLogistic(const std::vector<double>& scores, const std::vector<int>& labels) {
  double positives = 0;
  for (const int label : labels) positives += label;
  const double negatives = static_cast<double>(labels.size()) - positives;
  if (positives == 0 || negatives == 0) return {1.0, 0.0};
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
  return {a, b};
}

// The training windows of every region (true position, neighbours, displacements), normalised,
// one per column, with their targets: a Gaussian of the displacement, 1 pixel SD.
void trainingWindows(const Eigen::Ref<const Eigen::MatrixXf>& regions,
                     const ExpertTrainingSettings& settings, Eigen::MatrixXf& windows,
                     Eigen::VectorXf& targets) {
  const int patch = settings.patchSize;
  const int regionSize = patch + 2 * settings.radius;
  std::vector<std::vector<Offset>> offsets;
  Eigen::Index count = 0;
  for (Eigen::Index column = 0; column < regions.cols(); ++column) {
    offsets.push_back(offsetsFor(settings.seed, column, settings));
    count += static_cast<Eigen::Index>(offsets.back().size());
  }
  windows.resize(Eigen::Index(patch) * patch, count);
  targets.resize(count);
  Eigen::Index i = 0;
  for (Eigen::Index column = 0; column < regions.cols(); ++column) {
    for (const Offset offset : offsets[static_cast<std::size_t>(column)]) {
      auto x = windows.col(i);
      windowAt(regions.col(column).data(), regionSize, patch, settings.radius, offset, x);
      normalisePatch(x);
      targets[i++] = targetOf(offset);
    }
  }
}

// Mean squared error of the expert's responses to the windows' columns [begin, end).
double responseError(const PatchExpert& expert, const Eigen::MatrixXf& windows,
                     const Eigen::VectorXf& targets, Eigen::Index begin, Eigen::Index end) {
  if (end <= begin) return 0.0;
  const Eigen::MatrixXf scores =
      (expert.weights.transpose() * windows.middleCols(begin, end - begin)).colwise() + expert.bias;
  const Eigen::VectorXf response =
      (expert.alpha.transpose() * (1.0f + (-scores.array()).exp()).inverse().matrix()).transpose();
  return (response - targets.segment(begin, end - begin)).squaredNorm() /
         static_cast<double>(end - begin);
}

// Adam on one parameter block.
struct AdamState {
  Eigen::ArrayXXf m, v;
  void step(Eigen::Ref<Eigen::ArrayXXf> value, const Eigen::ArrayXXf& gradient, float rate, int t) {
    constexpr float kBeta1 = 0.9f;
    constexpr float kBeta2 = 0.999f;
    if (m.size() == 0) {
      m = Eigen::ArrayXXf::Zero(gradient.rows(), gradient.cols());
      v = m;
    }
    m = kBeta1 * m + (1.0f - kBeta1) * gradient;
    v = kBeta2 * v + (1.0f - kBeta2) * gradient.square();
    const float c1 = 1.0f - std::pow(kBeta1, static_cast<float>(t));
    const float c2 = 1.0f - std::pow(kBeta2, static_cast<float>(t));
    value -= rate * (m / c1) / ((v / c2).sqrt() + 1e-7f);
  }
};

// The one-unit expert as `units` units, the others silent (zero filter, bias and weight), so that
// every expert of a scale has the same units (the model file stores one count per scale).
PatchExpert padded(const PatchExpert& linear, int units) {
  PatchExpert expert;
  expert.weights = Eigen::MatrixXf::Zero(linear.weights.rows(), units);
  expert.bias = Eigen::VectorXf::Zero(units);
  expert.alpha = Eigen::VectorXf::Zero(units);
  expert.weights.col(0) = linear.weights.col(0);
  expert.bias[0] = linear.bias[0];
  expert.alpha[0] = linear.alpha[0];
  return expert;
}

// Grows a one-unit expert into a neural field of settings.units units: the units' responses
// summed with weights alpha, fitted to the windows' Gaussian targets by mini-batch Adam (squared
// error, a small weight decay; unit weights kept non-negative). The first unit starts as the
// linear expert, the others as small random filters, mostly off, with weight 0.1. The last tenth of
// the regions is held out: the neural field is kept only if it beats the linear expert there, else
// the linear expert is returned padded to the units.
PatchExpert trainNeuralField(const Eigen::Ref<const Eigen::MatrixXf>& regions,
                             const ExpertTrainingSettings& settings, const PatchExpert& linear) {
  Eigen::MatrixXf windows;
  Eigen::VectorXf targets;
  trainingWindows(regions, settings, windows, targets);
  const Eigen::Index total = windows.cols();
  const Eigen::Index heldOutRegions = regions.cols() / 10;
  // Windows are stored region by region with the same count per region.
  const Eigen::Index perRegion = total / regions.cols();
  const Eigen::Index trainCount = total - heldOutRegions * perRegion;
  if (trainCount < 64) return padded(linear, settings.units);

  const int units = settings.units;
  const Eigen::Index pixels = windows.rows();
  PatchExpert expert = padded(linear, units);
  SplitMixRandom random(mixKey(settings.seed, 0x6e657572616cULL));
  const float spread = 1.0f / std::sqrt(static_cast<float>(pixels));
  for (int k = 1; k < units; ++k) {
    for (Eigen::Index i = 0; i < pixels; ++i) {
      expert.weights(i, k) = spread * static_cast<float>(random.normal());
    }
    expert.weights.col(k).array() -= expert.weights.col(k).mean();
    expert.bias[k] = -2.0f;  // mostly off at first
    expert.alpha[k] = 0.1f;
  }

  // One shuffle of the training windows; mini-batches in that order every epoch.
  std::vector<Eigen::Index> order(static_cast<std::size_t>(trainCount));
  for (Eigen::Index i = 0; i < trainCount; ++i) order[static_cast<std::size_t>(i)] = i;
  for (std::size_t i = order.size(); i > 1; --i) {
    std::swap(order[i - 1],
              order[static_cast<std::size_t>(random.integer(0, static_cast<int>(i) - 1))]);
  }
  Eigen::MatrixXf shuffled(pixels, trainCount);
  Eigen::VectorXf shuffledTargets(trainCount);
  for (Eigen::Index i = 0; i < trainCount; ++i) {
    shuffled.col(i) = windows.col(order[static_cast<std::size_t>(i)]);
    shuffledTargets[i] = targets[order[static_cast<std::size_t>(i)]];
  }

  constexpr Eigen::Index kBatch = 256;
  constexpr float kDecay = 1e-4f;
  const Eigen::Index batches = (trainCount + kBatch - 1) / kBatch;
  const int steps = settings.epochs * static_cast<int>(batches);
  AdamState adamW, adamB, adamA;
  int t = 0;
  for (int epoch = 0; epoch < settings.epochs; ++epoch) {
    for (Eigen::Index b = 0; b < batches; ++b) {
      const Eigen::Index begin = b * kBatch;
      const Eigen::Index n = std::min(kBatch, trainCount - begin);
      const auto x = shuffled.middleCols(begin, n);
      const Eigen::ArrayXXf h =
          (1.0f + (-((expert.weights.transpose() * x).colwise() + expert.bias).array()).exp())
              .inverse();                                               // units x n
      const Eigen::ArrayXXf y = expert.alpha.transpose() * h.matrix();  // 1 x n
      const Eigen::ArrayXXf e =
          2.0f / static_cast<float>(n) *
          (y - shuffledTargets.segment(begin, n).transpose().array());  // dLoss / dy
      const Eigen::ArrayXXf gradAlpha = (h.matrix() * e.matrix().transpose()).array();
      const Eigen::ArrayXXf dz = (expert.alpha * e.matrix()).array() * h * (1.0f - h);
      Eigen::ArrayXXf gradW =
          (x * dz.matrix().transpose()).array() + kDecay * expert.weights.array();
      const Eigen::ArrayXXf gradB = dz.rowwise().sum();
      ++t;
      const float rate = settings.learningRate * (1.0f - 0.9f * static_cast<float>(t) / steps);
      Eigen::ArrayXXf w = expert.weights.array();
      adamW.step(w, gradW, rate, t);
      expert.weights = w.matrix();
      Eigen::ArrayXXf bias = expert.bias.array();
      adamB.step(bias, gradB, rate, t);
      expert.bias = bias.matrix().col(0);
      Eigen::ArrayXXf alpha = expert.alpha.array();
      adamA.step(alpha, gradAlpha, rate, t);
      // Non-negative unit weights, as in local neural fields: the response stays a non-negative
      // weight for the mean-shift, and no unit can say "not here".
      expert.alpha = alpha.max(0.0f).matrix().col(0);
    }
  }
  // Zero-mean filters: normalised windows are zero-mean, so this changes no score.
  for (int k = 0; k < units; ++k) expert.weights.col(k).array() -= expert.weights.col(k).mean();
  if (expert.weights.allFinite() && expert.bias.allFinite() && expert.alpha.allFinite() &&
      (heldOutRegions == 0 || responseError(expert, windows, targets, trainCount, total) <
                                  responseError(linear, windows, targets, trainCount, total))) {
    return expert;
  }
  return padded(linear, units);
}

// The logistic output of a filter: true positions against displacements of 2 pixels or more.
Eigen::Vector2d expertLogistic(const Eigen::Ref<const Eigen::MatrixXf>& regions,
                               const ExpertTrainingSettings& settings,
                               const Eigen::VectorXf& filter) {
  const int patch = settings.patchSize;
  const int regionSize = patch + 2 * settings.radius;
  std::vector<double> scores;
  std::vector<int> labels;
  Eigen::VectorXf x(patch * patch);
  for (Eigen::Index column = 0; column < regions.cols(); ++column) {
    const float* region = regions.col(column).data();
    for (const Offset offset : offsetsFor(settings.seed, column, settings)) {
      const int chebyshev = std::max(std::abs(offset.dx), std::abs(offset.dy));
      if (chebyshev == 1) continue;  // neither right nor wrong
      windowAt(region, regionSize, patch, settings.radius, offset, x);
      normalisePatch(x);
      scores.push_back(filter.dot(x));
      labels.push_back(chebyshev == 0 ? 1 : 0);
    }
  }
  return fitLogistic(scores, labels);
}

void checkExpertRegions(const Eigen::Ref<const Eigen::MatrixXf>& regions,
                        const ExpertTrainingSettings& settings) {
  const int patch = settings.patchSize;
  const int regionSize = patch + 2 * settings.radius;
  if (patch < 2 || settings.radius < 1) throw Error("expert training: bad patch size or radius");
  if (settings.units < 1 || settings.epochs < 1)
    throw Error("expert training: bad units or epochs");
  if (regions.cols() == 0) throw Error("expert training: no regions");
  if (regions.rows() != Eigen::Index(regionSize) * regionSize) {
    throw Error("expert training: regions of " + std::to_string(regions.rows()) +
                " values, expected " + std::to_string(regionSize * regionSize));
  }
}

}  // namespace

PatchExpert adaptPatchExpert(const Eigen::Ref<const Eigen::MatrixXf>& regions,
                             const ExpertTrainingSettings& settings, const PatchExpert& general,
                             double priorRegions) {
  checkExpertRegions(regions, settings);
  const int patch = settings.patchSize;
  const int pixels = patch * patch;
  if (general.units() != 1 || general.weights.rows() != pixels) {
    throw Error("expert adaptation: the general expert has " + std::to_string(general.units()) +
                " units of " + std::to_string(general.weights.rows()) +
                " weights; only one-unit experts of " + std::to_string(pixels) + " are adapted");
  }
  if (!(priorRegions >= 0.0)) throw Error("expert adaptation: negative prior weight");
  Eigen::MatrixXf windows;
  Eigen::VectorXf targets;
  trainingWindows(regions, settings, windows, targets);
  const Eigen::MatrixXd x = windows.cast<double>();
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(pixels, pixels);
  gram.selfadjointView<Eigen::Lower>().rankUpdate(x);
  gram.triangularView<Eigen::StrictlyUpper>() = gram.transpose();
  Eigen::VectorXd rhs = x * targets.cast<double>();
  // Normalised windows have unit variance, so each adds about 1 to every diagonal entry: a prior
  // of priorRegions regions weighs as many regions' windows would.
  const double windowsPerRegion = static_cast<double>(windows.cols()) / regions.cols();
  const double prior = std::max(priorRegions * windowsPerRegion, 1e-6);
  const Eigen::VectorXd generalFilter = general.weights.col(0).cast<double>();
  gram.diagonal().array() += prior;
  rhs += prior * generalFilter;
  Eigen::VectorXd weights = gram.ldlt().solve(rhs);
  if (!weights.allFinite()) throw Error("expert adaptation: the regression did not solve");
  weights.array() -= weights.mean();
  const Eigen::VectorXf filter = weights.cast<float>();
  const Eigen::Vector2d logistic = expertLogistic(regions, settings, filter);
  return PatchExpert::logistic(filter, static_cast<float>(logistic[0]),
                               static_cast<float>(logistic[1]));
}

PatchExpert trainPatchExpert(const Eigen::Ref<const Eigen::MatrixXf>& regions,
                             const ExpertTrainingSettings& settings) {
  checkExpertRegions(regions, settings);
  const int patch = settings.patchSize;
  const int regionSize = patch + 2 * settings.radius;
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
      targets[filled] = targetOf(offset);
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

  const Eigen::VectorXf filter = weights.cast<float>();
  const Eigen::Vector2d logistic = expertLogistic(regions, settings, filter);
  const PatchExpert linear = PatchExpert::logistic(filter, static_cast<float>(logistic[0]),
                                                   static_cast<float>(logistic[1]));
  return settings.units > 1 ? trainNeuralField(regions, settings, linear) : linear;
}

}  // namespace clm3d
