// Principal component analysis: the linear model x ~ mean + P b behind both the shape model and
// the texture (patch) models. One implementation, deterministic (eigenvector signs fixed), so a
// model trained twice on the same data is bit-identical.
#pragma once

#include <Eigen/Core>

namespace clm3d {

// The principal axes of centred samples (D x N, one per column, already mean-subtracted), in
// double precision: the shared core of fitPca and the shape model. Same selection rules as fitPca.
struct PcaBasis {
  Eigen::MatrixXd components;  // D x K, orthonormal columns, signs fixed
  Eigen::VectorXd variances;   // K, descending
};
PcaBasis principalAxes(const Eigen::MatrixXd& centred, double varianceKept, int maxModes = 0);

struct PcaModel {
  Eigen::VectorXf mean;        // D
  Eigen::MatrixXf components;  // D x K, orthonormal columns
  Eigen::VectorXf variances;   // K, descending (eigenvalues of the sample covariance)

  int dimension() const { return static_cast<int>(mean.size()); }
  int modeCount() const { return static_cast<int>(components.cols()); }
  // b = P^T (x - mean). x must have dimension() entries.
  Eigen::VectorXf project(const Eigen::Ref<const Eigen::VectorXf>& x) const;
  // mean + P b. b must have modeCount() entries.
  Eigen::VectorXf reconstruct(const Eigen::Ref<const Eigen::VectorXf>& b) const;
};

// samples: D x N, one sample per column (N >= 1). Keeps the fewest modes whose variances sum to
// >= varianceKept (in (0, 1]) of the total, at most maxModes if maxModes > 0, and never a mode of
// (numerically) zero variance. Covariance is normalised by N (population). Uses the N x N Gram
// matrix when N < D. Each component's sign is fixed so that its largest-magnitude entry is
// positive. Throws Error on an empty sample matrix, non-finite values or varianceKept out of range.
PcaModel fitPca(const Eigen::MatrixXf& samples, double varianceKept, int maxModes = 0);

}  // namespace clm3d
