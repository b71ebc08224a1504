#include "core/scheme/landmark_set.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace clm3d {

LandmarkSet::LandmarkSet(int count, int dims) : dims_(dims) {
  if (dims != 2 && dims != 3) {
    throw std::invalid_argument("a landmark set has 2 or 3 dimensions, not " +
                                std::to_string(dims));
  }
  if (count < 0) throw std::invalid_argument("negative landmark count");
  points_ = Eigen::Matrix3Xd::Zero(3, count);
  present_.assign(static_cast<std::size_t>(count), false);
}

void LandmarkSet::checkIndex(int i) const {
  if (i < 0 || i >= size()) {
    throw std::out_of_range("landmark index " + std::to_string(i) + " out of range for a set of " +
                            std::to_string(size()));
  }
}

bool LandmarkSet::has(int i) const {
  checkIndex(i);
  return present_[static_cast<std::size_t>(i)];
}

Eigen::Vector3d LandmarkSet::point(int i) const {
  if (!has(i)) throw std::logic_error("landmark " + std::to_string(i) + " is missing");
  return points_.col(i);
}

void LandmarkSet::set(int i, const Eigen::Vector3d& p) {
  checkIndex(i);
  if (!p.allFinite()) {
    throw std::invalid_argument("landmark " + std::to_string(i) + " set to a non-finite value");
  }
  points_.col(i) = p;
  if (dims_ == 2) points_(2, i) = 0.0;
  present_[static_cast<std::size_t>(i)] = true;
}

void LandmarkSet::set(int i, const Eigen::Vector2d& p) {
  set(i, Eigen::Vector3d(p.x(), p.y(), 0.0));
}

void LandmarkSet::setMissing(int i) {
  checkIndex(i);
  points_.col(i).setZero();
  present_[static_cast<std::size_t>(i)] = false;
}

int LandmarkSet::presentCount() const {
  int count = 0;
  for (const bool p : present_) count += p ? 1 : 0;
  return count;
}

Eigen::Vector3d LandmarkSet::centroid() const {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (int i = 0; i < size(); ++i) {
    if (!present_[static_cast<std::size_t>(i)]) continue;
    sum += points_.col(i);
    ++count;
  }
  return count > 0 ? Eigen::Vector3d(sum / count) : sum;
}

Eigen::Matrix3Xd LandmarkSet::matrix() const {
  Eigen::Matrix3Xd result = points_;
  for (int i = 0; i < size(); ++i) {
    if (!present_[static_cast<std::size_t>(i)]) {
      result.col(i).setConstant(std::numeric_limits<double>::quiet_NaN());
    }
  }
  return result;
}

bool LandmarkSet::operator==(const LandmarkSet& other) const {
  return dims_ == other.dims_ && present_ == other.present_ && points_ == other.points_;
}

}  // namespace clm3d
