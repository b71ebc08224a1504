#include "core/refine/detail/ridge_regression.hpp"

#include <Eigen/Dense>

namespace clm3d {

Eigen::MatrixXf ridgeRegression(const Eigen::MatrixXf& features, const Eigen::MatrixXf& targets,
                                double ridge) {
  const Eigen::Index d = features.rows(), m = features.cols();
  const double lambda = ridge * features.cast<double>().squaredNorm() / static_cast<double>(d);
  if (m < d) {
    // With fewer samples than features: W = T (F^T F + lambda I)^-1 F^T.
    Eigen::MatrixXd kernel = (features.transpose() * features).cast<double>();
    kernel.diagonal().array() += lambda;
    const Eigen::MatrixXd dual = kernel.llt().solve(targets.transpose().cast<double>());
    return (features.cast<double>() * dual).transpose().cast<float>();
  }
  Eigen::MatrixXd gram = (features * features.transpose()).cast<double>();
  gram.diagonal().array() += lambda;
  const Eigen::MatrixXd rhs = (features * targets.transpose()).cast<double>();
  return gram.llt().solve(rhs).transpose().cast<float>();
}

}  // namespace clm3d
