#include "core/model/pca.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "core/common/error.hpp"

namespace clm3d {

namespace {

// Largest-magnitude entry positive (the first of equal magnitudes), so results are reproducible.
void fixSign(Eigen::Ref<Eigen::VectorXd> v) {
  Eigen::Index best = 0;
  for (Eigen::Index i = 1; i < v.size(); ++i) {
    if (std::abs(v[i]) > std::abs(v[best])) best = i;
  }
  if (v.size() > 0 && v[best] < 0) v = -v;
}

}  // namespace

PcaBasis principalAxes(const Eigen::MatrixXd& centred, double varianceKept, int maxModes) {
  if (!(varianceKept > 0.0 && varianceKept <= 1.0)) {
    throw Error("PCA: variance kept must be in (0, 1], got " + std::to_string(varianceKept));
  }
  const Eigen::Index d = centred.rows();
  const Eigen::Index n = centred.cols();
  if (d == 0 || n == 0) throw Error("PCA: no samples");
  if (!centred.allFinite()) throw Error("PCA: samples contain non-finite values");

  // Eigen-decomposition of the smaller of the covariance (D x D) and the Gram matrix (N x N); both
  // share the non-zero eigenvalues. Eigen returns eigenvalues ascending.
  const bool gram = n < d;
  Eigen::MatrixXd small = gram ? Eigen::MatrixXd(centred.transpose() * centred)
                               : Eigen::MatrixXd(centred * centred.transpose());
  small /= static_cast<double>(n);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(small);
  if (solver.info() != Eigen::Success) throw Error("PCA: eigen-decomposition failed");
  const Eigen::VectorXd& values = solver.eigenvalues();

  double total = 0.0;
  for (Eigen::Index i = 0; i < values.size(); ++i) total += std::max(values[i], 0.0);
  const double negligible = 1e-12 * total;
  const double target = varianceKept * total * (1.0 - 1e-12);

  Eigen::Index keep = 0;
  double sum = 0.0;
  for (Eigen::Index i = values.size() - 1; i >= 0; --i) {
    if (values[i] <= negligible || (maxModes > 0 && keep >= maxModes)) break;
    ++keep;
    sum += values[i];
    if (sum >= target) break;
  }

  PcaBasis basis;
  basis.components.resize(d, keep);
  basis.variances.resize(keep);
  for (Eigen::Index k = 0; k < keep; ++k) {
    const Eigen::Index source = values.size() - 1 - k;
    basis.variances[k] = values[source];
    if (gram) {
      Eigen::VectorXd axis = centred * solver.eigenvectors().col(source);
      axis.normalize();
      basis.components.col(k) = axis;
    } else {
      basis.components.col(k) = solver.eigenvectors().col(source);
    }
    fixSign(basis.components.col(k));
  }
  return basis;
}

PcaModel fitPca(const Eigen::MatrixXf& samples, double varianceKept, int maxModes) {
  if (samples.rows() == 0 || samples.cols() == 0) throw Error("PCA: no samples");
  if (!samples.allFinite()) throw Error("PCA: samples contain non-finite values");
  const Eigen::MatrixXd data = samples.cast<double>();
  const Eigen::VectorXd mean = data.rowwise().mean();
  const Eigen::MatrixXd centred = data.colwise() - mean;
  const PcaBasis basis = principalAxes(centred, varianceKept, maxModes);
  PcaModel model;
  model.mean = mean.cast<float>();
  model.components = basis.components.cast<float>();
  model.variances = basis.variances.cast<float>();
  return model;
}

Eigen::VectorXf PcaModel::project(const Eigen::Ref<const Eigen::VectorXf>& x) const {
  if (x.size() != mean.size()) {
    throw Error("PCA: vector of size " + std::to_string(x.size()) + " projected onto a model of " +
                "dimension " + std::to_string(mean.size()));
  }
  return components.transpose() * (x - mean);
}

Eigen::VectorXf PcaModel::reconstruct(const Eigen::Ref<const Eigen::VectorXf>& b) const {
  if (b.size() != components.cols()) {
    throw Error("PCA: " + std::to_string(b.size()) + " parameters for a model of " +
                std::to_string(components.cols()) + " modes");
  }
  return mean + components * b;
}

}  // namespace clm3d
