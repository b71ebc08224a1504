// A set of landmark points, 2D (image pixels) or 3D (model millimetres), any of which may be
// missing (not annotated, occluded, or without a counterpart after conversion). The one
// in-memory form that every reader produces and every stage consumes.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace clm3d {

class LandmarkSet {
 public:
  LandmarkSet() : LandmarkSet(0, 2) {}
  // count points, all missing; dims is 2 or 3 (std::invalid_argument otherwise).
  LandmarkSet(int count, int dims);

  int size() const { return static_cast<int>(present_.size()); }
  int dims() const { return dims_; }
  bool has(int i) const;
  // The point (z = 0 for a 2D set). Throws std::logic_error if it is missing.
  Eigen::Vector3d point(int i) const;
  // Sets a point; a 2D set keeps z = 0. Coordinates must be finite (std::invalid_argument).
  void set(int i, const Eigen::Vector3d& p);
  void set(int i, const Eigen::Vector2d& p);
  void setMissing(int i);
  int presentCount() const;
  // The mean of the present points (the origin when none is present).
  Eigen::Vector3d centroid() const;
  // All points as columns; missing points are NaN columns.
  Eigen::Matrix3Xd matrix() const;
  std::vector<bool> presentMask() const { return present_; }

  bool operator==(const LandmarkSet& other) const;

 private:
  void checkIndex(int i) const;

  int dims_;
  Eigen::Matrix3Xd points_;
  std::vector<bool> present_;
};

}  // namespace clm3d
