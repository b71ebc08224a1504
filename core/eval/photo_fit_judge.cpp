#include "core/eval/detail/photo_fit_judge.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

#include "core/common/logistic_curve.hpp"
#include "core/eval/detail/confidence_roc.hpp"

namespace clm3d {
namespace {

constexpr int kMaxComponents = 50;
constexpr int kFolds = 5;
// The penalty on the components' weights, in units of the sample count times the features' mean
// variance (so that it means the same for any number of fits and any feature scale).
constexpr std::array<double, 8> kRelativePenalties{1e-3, 1e-2, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0};

// The leading principal components of centred rows: the rows' scores on them and the directions
// in feature space (as columns).
struct Components {
  Eigen::RowVectorXd mean;
  Eigen::MatrixXd directions;  // features x k
  double meanVariance = 0.0;   // of the features
};

Components componentsOf(const Eigen::MatrixXd& rows) {
  Components c;
  const auto n = rows.rows();
  c.mean = rows.colwise().mean();
  const Eigen::MatrixXd centred = rows.rowwise() - c.mean;
  // Through the n x n Gram matrix: there are far fewer fits than features.
  const Eigen::MatrixXd gram = centred * centred.transpose();
  c.meanVariance = gram.trace() / static_cast<double>(n * rows.cols());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  const Eigen::Index k = std::min<Eigen::Index>({kMaxComponents, n / kFolds, n - 1});
  c.directions.resize(rows.cols(), 0);
  std::vector<Eigen::VectorXd> kept;
  for (Eigen::Index j = n - 1; j >= 0 && static_cast<Eigen::Index>(kept.size()) < k; --j) {
    const double value = eigen.eigenvalues()(j);
    if (!(value > 1e-9 * gram.trace())) break;
    kept.push_back(centred.transpose() * eigen.eigenvectors().col(j) / std::sqrt(value));
  }
  c.directions.resize(rows.cols(), static_cast<Eigen::Index>(kept.size()));
  for (std::size_t j = 0; j < kept.size(); ++j)
    c.directions.col(static_cast<Eigen::Index>(j)) = kept[j];
  return c;
}

// Inputs of the regression: the components' scores, the log-odds, 1.
Eigen::MatrixXd inputsOf(const Eigen::MatrixXd& rows, const std::vector<double>& logOdds,
                         const Components& c) {
  const Eigen::Index k = c.directions.cols();
  Eigen::MatrixXd inputs(rows.rows(), k + 2);
  inputs.leftCols(k) = (rows.rowwise() - c.mean) * c.directions;
  for (Eigen::Index i = 0; i < rows.rows(); ++i) {
    inputs(i, k) = logOdds[static_cast<std::size_t>(i)];
    inputs(i, k + 1) = 1.0;
  }
  return inputs;
}

Eigen::VectorXd fitJudge(const Eigen::MatrixXd& inputs, const std::vector<bool>& right,
                         double penalty) {
  const Eigen::Index k = inputs.cols() - 2;
  Eigen::VectorXd penalties = Eigen::VectorXd::Zero(k + 2);
  penalties.head(k).setConstant(penalty);
  Eigen::VectorXd start = Eigen::VectorXd::Zero(k + 2);
  start(k) = 1.0;  // the check's own log-odds
  return fitLogisticRegression(inputs, right, penalties, start);
}

double rocArea(const Eigen::VectorXd& scores, const std::vector<bool>& right) {
  std::vector<ScoredFit> fits;
  for (Eigen::Index i = 0; i < scores.size(); ++i)
    fits.push_back({scores(i), right[static_cast<std::size_t>(i)] ? 0.0 : 1.0});
  return confidenceRoc(fits, 0.5).auc;
}

}  // namespace

PhotoFitCurve learnPhotoFitJudge(double viewYawDeg, const PhotoFitSample& sample) {
  const Eigen::MatrixXd rows = sample.features.cast<double>();
  const auto n = static_cast<std::size_t>(rows.rows());
  // Cross-validation: every kFolds-th fit held out in turn, the components learnt without it.
  // Per fold that has both kinds: each penalty's held-out ROC area, and the log-odds' alone.
  std::vector<std::array<double, kRelativePenalties.size()>> area;
  std::vector<double> checkArea;
  for (int fold = 0; fold < kFolds; ++fold) {
    std::vector<Eigen::Index> learn, held;
    for (std::size_t i = 0; i < n; ++i)
      (static_cast<int>(i % kFolds) == fold ? held : learn).push_back(static_cast<Eigen::Index>(i));
    const auto pick = [&](const std::vector<Eigen::Index>& at, Eigen::MatrixXd& r,
                          std::vector<double>& lo, std::vector<bool>& y) {
      r.resize(static_cast<Eigen::Index>(at.size()), rows.cols());
      for (std::size_t j = 0; j < at.size(); ++j) {
        r.row(static_cast<Eigen::Index>(j)) = rows.row(at[j]);
        lo.push_back(sample.logOdds[static_cast<std::size_t>(at[j])]);
        y.push_back(sample.right[static_cast<std::size_t>(at[j])]);
      }
    };
    Eigen::MatrixXd learnRows, heldRows;
    std::vector<double> learnLo, heldLo;
    std::vector<bool> learnRight, heldRight;
    pick(learn, learnRows, learnLo, learnRight);
    pick(held, heldRows, heldLo, heldRight);
    const auto heldRightCount = std::count(heldRight.begin(), heldRight.end(), true);
    const auto learnRightCount = std::count(learnRight.begin(), learnRight.end(), true);
    if (heldRightCount == 0 || heldRightCount == static_cast<long>(heldRight.size()) ||
        learnRightCount == 0 || learnRightCount == static_cast<long>(learnRight.size()))
      continue;  // a fold without both kinds ranks nothing (only in tiny samples)
    const Components c = componentsOf(learnRows);
    const Eigen::MatrixXd learnInputs = inputsOf(learnRows, learnLo, c);
    const Eigen::MatrixXd heldInputs = inputsOf(heldRows, heldLo, c);
    auto& areas = area.emplace_back();
    for (std::size_t p = 0; p < kRelativePenalties.size(); ++p) {
      const double penalty =
          kRelativePenalties[p] * c.meanVariance * static_cast<double>(learn.size());
      areas[p] = rocArea(heldInputs * fitJudge(learnInputs, learnRight, penalty), heldRight);
    }
    checkArea.push_back(rocArea(
        Eigen::Map<const Eigen::VectorXd>(heldLo.data(), static_cast<Eigen::Index>(heldLo.size())),
        heldRight));
  }
  // The best mean area; among equal ones the strongest penalty.
  const auto folds = static_cast<double>(area.size());
  const auto meanArea = [&](std::size_t p) {
    double sum = 0.0;
    for (const auto& areas : area) sum += areas[p];
    return sum / folds;
  };
  std::size_t best = 0;
  for (std::size_t p = 1; p < kRelativePenalties.size(); ++p)
    if (meanArea(p) >= meanArea(best)) best = p;
  // The image term is kept only where it ranks the held-out fits better than the check's
  // log-odds alone by more than one standard error of the folds' paired differences (the
  // one-standard-error rule: the simpler judge unless the data show the other is better). Near
  // the frontal view the check already reads the face and the term is mostly noise.
  double gain = 0.0, spread = 0.0;
  for (std::size_t f = 0; f < area.size(); ++f) gain += (area[f][best] - checkArea[f]) / folds;
  for (std::size_t f = 0; f < area.size(); ++f)
    spread += std::pow(area[f][best] - checkArea[f] - gain, 2.0);
  const double standardError = folds > 1 ? std::sqrt(spread / (folds - 1) / folds) : 0.0;
  if (area.size() < 2 || gain <= standardError) {
    const LogisticCurve alone = fitLogisticCurve(sample.logOdds, sample.right);
    return {viewYawDeg, alone.slope, alone.offset, {}, {}};
  }

  const Components c = componentsOf(rows);
  const Eigen::MatrixXd inputs = inputsOf(rows, sample.logOdds, c);
  const Eigen::VectorXd w = fitJudge(
      inputs, sample.right, kRelativePenalties[best] * c.meanVariance * static_cast<double>(n));
  const Eigen::Index k = c.directions.cols();
  PhotoFitCurve curve;
  curve.viewYawDeg = viewYawDeg;
  curve.slope = w(k);
  curve.offset = w(k + 1);
  curve.imageMean = c.mean.transpose().cast<float>();
  curve.imageWeights = (c.directions * w.head(k)).cast<float>();
  return curve;
}

}  // namespace clm3d
