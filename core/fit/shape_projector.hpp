// Projects the shape model, at parameters p (fit_state.hpp), to pixels of one pyramid level of the
// working image, with the analytic Jacobian d(points)/dp that the Gauss-Newton and FastNCC updates
// chain with the patch gradients. Works on a subset of landmarks (a view's visible ones) and
// allocates nothing after setup, so it can run inside the optimisers' inner loops.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/fit/fit_state.hpp"
#include "core/fit/working_image.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/shape_model.hpp"

namespace clm3d {

class ShapeProjector {
 public:
  ShapeProjector(const ShapeModel& shape, const Camera& camera);

  // The landmarks to project (indices into the shape's points), in output order.
  void setLandmarks(const std::vector<int>& landmarks);
  // Output pixels at `level` of `image` (level -1 or no call: input pixels).
  void setLevel(const WorkingImage& image, int level);
  void setInputPixels();
  // Tz of the pose (p does not hold it).
  void setDepth(double tz) { depth_ = tz; }
  double depth() const { return depth_; }

  int paramCount() const { return kPoseParamCount + modeCount_; }
  int landmarkCount() const { return static_cast<int>(landmarks_.size()); }
  const std::vector<int>& landmarks() const { return landmarks_; }
  // True for the 2D shape model: pitch and yaw stay 0 (their Jacobian columns are zero).
  bool planar() const { return planar_; }

  // 2 x landmarkCount() pixel positions. `out` must already have that size (it is not resized).
  void project(const Eigen::Ref<const Eigen::VectorXd>& p, Eigen::Ref<Eigen::Matrix2Xd> out) const;
  // d(points)/dp, 2*landmarkCount() x paramCount(), rows (x_1, y_1, x_2, y_2, ...). Also writes
  // the points to `points` when it is not null. `out` must already have the right size.
  void jacobian(const Eigen::Ref<const Eigen::VectorXd>& p, Eigen::Ref<Eigen::MatrixXd> out,
                Eigen::Matrix2Xd* points = nullptr) const;

  // Per parameter, a change that moves the projected points by about one pixel (RMS) at p; 0 for
  // a parameter that does not move them (pitch and yaw of the planar model). Optimisers use these
  // as natural units (initial steps, particle spreads, simplex size).
  Eigen::VectorXd unitSteps(const Eigen::Ref<const Eigen::VectorXd>& p) const;
  // The same into `out` (resized to paramCount()), allocating nothing once sized: for the
  // optimisers that take unit steps on every iteration.
  void unitSteps(const Eigen::Ref<const Eigen::VectorXd>& p, Eigen::VectorXd& out) const;

  // Keeps p valid: shape coefficients within the model's +-limitSd, scale positive, pitch and
  // yaw 0 for the planar model, angles within (-90, 90) degrees.
  void clamp(Eigen::Ref<Eigen::VectorXd> p) const;

 private:
  // Eye coordinates to output pixels: u = cx + fx x / -z, v = cy - fy y / -z.
  struct PixelMap {
    double fx, fy, cx, cy;
  };
  PixelMap pixelMap() const;
  // The subset's landmark j in model coordinates for the shape coefficients b.
  Eigen::Vector3d modelPoint(int j, const Eigen::Ref<const Eigen::VectorXd>& b) const;

  const ShapeModel* shape_;
  Camera camera_;
  int modeCount_ = 0;
  bool planar_ = false;
  std::vector<int> landmarks_;
  Eigen::Matrix3Xd mean_;  // 3 x m, the subset's mean shape
  Eigen::MatrixXd modes_;  // 3m x K, the subset's rows
  Eigen::Vector2d gain_{1.0, 1.0};
  Eigen::Vector2d offset_{0.0, 0.0};
  double depth_ = -1000.0;
  mutable Eigen::MatrixXd stepJacobian_;  // scratch of unitSteps
};

// Every landmark of the shape model at `state`, in input pixels of `camera` (2 x points).
Eigen::Matrix2Xd projectShape(const ShapeModel& shape, const Camera& camera, const FitState& state);

}  // namespace clm3d
