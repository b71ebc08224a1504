#include "core/geometry/procrustes.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

Eigen::Matrix3Xd selectColumns(const Eigen::Matrix3Xd& points, const std::vector<bool>& use) {
  if (use.empty()) return points;
  Eigen::Index count = 0;
  for (bool u : use) count += u ? 1 : 0;
  Eigen::Matrix3Xd selected(3, count);
  Eigen::Index next = 0;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    if (use[static_cast<std::size_t>(i)]) selected.col(next++) = points.col(i);
  }
  return selected;
}

}  // namespace

Eigen::Matrix3Xd Similarity3::apply(const Eigen::Matrix3Xd& points) const {
  return ((scale * rotation) * points).colwise() + translation;
}

Similarity3 Similarity3::inverse() const {
  Similarity3 inv;
  inv.scale = 1.0 / scale;
  inv.rotation = rotation.transpose();
  inv.translation = -(inv.scale * (inv.rotation * translation));
  return inv;
}

Similarity3 alignSimilarity(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                            const std::vector<bool>& use, bool allowScale) {
  if (source.cols() != target.cols()) throw Error("procrustes: point counts differ");
  if (!use.empty() && use.size() != static_cast<std::size_t>(source.cols())) {
    throw Error("procrustes: selection size differs from point count");
  }
  const Eigen::Matrix3Xd src = selectColumns(source, use);
  const Eigen::Matrix3Xd dst = selectColumns(target, use);
  if (src.cols() < 3) throw Error("procrustes: need at least 3 corresponding points");
  if (!src.allFinite() || !dst.allFinite()) throw Error("procrustes: non-finite coordinates");

  // Umeyama (1991): centre both sets, SVD of the cross-covariance, fix reflections.
  const Eigen::Vector3d srcMean = src.rowwise().mean();
  const Eigen::Vector3d dstMean = dst.rowwise().mean();
  const Eigen::Matrix3Xd srcCentred = src.colwise() - srcMean;
  const Eigen::Matrix3Xd dstCentred = dst.colwise() - dstMean;
  const double n = static_cast<double>(src.cols());
  const double srcVariance = srcCentred.squaredNorm() / n;
  if (srcVariance <= 1e-18) throw Error("procrustes: source points coincide");

  const Eigen::Matrix3d covariance = dstCentred * srcCentred.transpose() / n;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d singular = svd.singularValues();
  if (singular(1) <= 1e-12 * std::max(1.0, singular(0))) {
    throw Error("procrustes: points are collinear, rotation is undetermined");
  }
  Eigen::Vector3d sign = Eigen::Vector3d::Ones();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) sign(2) = -1.0;

  Similarity3 result;
  result.rotation = svd.matrixU() * sign.asDiagonal() * svd.matrixV().transpose();
  result.scale = allowScale ? singular.dot(sign) / srcVariance : 1.0;
  result.translation = dstMean - result.scale * result.rotation * srcMean;
  return result;
}

double rmsDistance(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b,
                   const std::vector<bool>& use) {
  if (a.cols() != b.cols()) throw Error("rmsDistance: point counts differ");
  const Eigen::Matrix3Xd sa = selectColumns(a, use);
  const Eigen::Matrix3Xd sb = selectColumns(b, use);
  if (sa.cols() == 0) return 0.0;
  return std::sqrt((sa - sb).colwise().squaredNorm().mean());
}

}  // namespace clm3d
