#include "core/fit/shape_projector.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

struct Rotations {
  Eigen::Matrix3d x, y, z;     // Rx(pitch), Ry(yaw), Rz(roll)
  Eigen::Matrix3d dx, dy, dz;  // their derivatives
};

Rotations rotations(double pitch, double yaw, double roll) {
  Rotations r;
  const double cx = std::cos(pitch), sx = std::sin(pitch);
  const double cy = std::cos(yaw), sy = std::sin(yaw);
  const double cz = std::cos(roll), sz = std::sin(roll);
  r.x << 1, 0, 0, 0, cx, -sx, 0, sx, cx;
  r.y << cy, 0, sy, 0, 1, 0, -sy, 0, cy;
  r.z << cz, -sz, 0, sz, cz, 0, 0, 0, 1;
  r.dx << 0, 0, 0, 0, -sx, -cx, 0, cx, -sx;
  r.dy << -sy, 0, cy, 0, 0, 0, -cy, 0, -sy;
  r.dz << -sz, -cz, 0, cz, -sz, 0, 0, 0, 0;
  return r;
}

}  // namespace

ShapeProjector::ShapeProjector(const ShapeModel& shape, const Camera& camera)
    : shape_(&shape), camera_(camera), modeCount_(shape.modeCount()), planar_(shape.dims == 2) {
  std::vector<int> all(static_cast<std::size_t>(shape.pointCount()));
  for (int i = 0; i < shape.pointCount(); ++i) all[static_cast<std::size_t>(i)] = i;
  setLandmarks(all);
}

void ShapeProjector::setLandmarks(const std::vector<int>& landmarks) {
  const int m = static_cast<int>(landmarks.size());
  if (landmarks == landmarks_ && mean_.cols() == m) return;
  for (const int i : landmarks) {
    if (i < 0 || i >= shape_->pointCount()) throw Error("fit: landmark index out of range");
  }
  landmarks_ = landmarks;
  mean_.resize(3, m);
  modes_.resize(3 * m, modeCount_);
  for (int j = 0; j < m; ++j) {
    const int i = landmarks[static_cast<std::size_t>(j)];
    mean_.col(j) = shape_->meanShape.col(i);
    modes_.middleRows(3 * j, 3) = shape_->modes.middleRows(3 * i, 3);
  }
}

void ShapeProjector::setLevel(const WorkingImage& image, int level) {
  const double divisor = std::ldexp(1.0, level);
  gain_ = image.gain / divisor;
  offset_ = image.offset / divisor;
}

void ShapeProjector::setInputPixels() {
  gain_ = {1.0, 1.0};
  offset_ = {0.0, 0.0};
}

ShapeProjector::PixelMap ShapeProjector::pixelMap() const {
  return {camera_.focalX() * gain_.x(), camera_.focalY() * gain_.y(),
          (0.5 * camera_.width - 0.5) * gain_.x() + offset_.x(),
          (0.5 * camera_.height - 0.5) * gain_.y() + offset_.y()};
}

Eigen::Vector3d ShapeProjector::modelPoint(int j,
                                           const Eigen::Ref<const Eigen::VectorXd>& b) const {
  return mean_.col(j) + modes_.middleRows(3 * j, 3) * b;
}

void ShapeProjector::project(const Eigen::Ref<const Eigen::VectorXd>& p,
                             Eigen::Ref<Eigen::Matrix2Xd> out) const {
  const Rotations r = rotations(p[kParamPitch], p[kParamYaw], p[kParamRoll]);
  const Eigen::Matrix3d sr = p[kParamScale] * (r.x * r.y * r.z);
  const Eigen::Vector3d t(p[kParamTx], p[kParamTy], depth_);
  const PixelMap map = pixelMap();
  const auto b = p.tail(modeCount_);
  for (int j = 0; j < landmarkCount(); ++j) {
    const Eigen::Vector3d e = t + sr * modelPoint(j, b);
    const double w = -e.z();
    out(0, j) = map.cx + map.fx * e.x() / w;
    out(1, j) = map.cy - map.fy * e.y() / w;
  }
}

void ShapeProjector::jacobian(const Eigen::Ref<const Eigen::VectorXd>& p,
                              Eigen::Ref<Eigen::MatrixXd> out, Eigen::Matrix2Xd* points) const {
  const Rotations r = rotations(p[kParamPitch], p[kParamYaw], p[kParamRoll]);
  const double scale = p[kParamScale];
  const Eigen::Matrix3d rotation = r.x * r.y * r.z;
  const Eigen::Matrix3d sr = scale * rotation;
  const Eigen::Matrix3d dPitch = scale * (r.dx * r.y * r.z);
  const Eigen::Matrix3d dYaw = scale * (r.x * r.dy * r.z);
  const Eigen::Matrix3d dRoll = scale * (r.x * r.y * r.dz);
  const Eigen::Vector3d t(p[kParamTx], p[kParamTy], depth_);
  const PixelMap map = pixelMap();
  const auto b = p.tail(modeCount_);
  for (int j = 0; j < landmarkCount(); ++j) {
    const Eigen::Vector3d s = modelPoint(j, b);
    const Eigen::Vector3d e = t + sr * s;
    const double w = -e.z();
    // d(u, v)/de of the pixel map with w = -ez.
    Eigen::Matrix<double, 2, 3> de;
    de << map.fx / w, 0.0, map.fx * e.x() / (w * w), 0.0, -map.fy / w, -map.fy * e.y() / (w * w);
    if (points != nullptr) {
      (*points)(0, j) = map.cx + map.fx * e.x() / w;
      (*points)(1, j) = map.cy - map.fy * e.y() / w;
    }
    auto rows = out.middleRows(2 * j, 2);
    rows.col(kParamTx) = de.col(0);
    rows.col(kParamTy) = de.col(1);
    rows.col(kParamScale) = de * (rotation * s);
    rows.col(kParamPitch) = planar_ ? Eigen::Vector2d::Zero() : Eigen::Vector2d(de * (dPitch * s));
    rows.col(kParamYaw) = planar_ ? Eigen::Vector2d::Zero() : Eigen::Vector2d(de * (dYaw * s));
    rows.col(kParamRoll) = de * (dRoll * s);
    rows.rightCols(modeCount_).noalias() = (de * sr) * modes_.middleRows(3 * j, 3);
  }
}

Eigen::VectorXd ShapeProjector::unitSteps(const Eigen::Ref<const Eigen::VectorXd>& p) const {
  Eigen::VectorXd steps;
  unitSteps(p, steps);
  return steps;
}

void ShapeProjector::unitSteps(const Eigen::Ref<const Eigen::VectorXd>& p,
                               Eigen::VectorXd& steps) const {
  stepJacobian_.resize(2 * landmarkCount(), paramCount());
  jacobian(p, stepJacobian_);
  steps.resize(paramCount());
  const double points = std::max(1, landmarkCount());
  for (int k = 0; k < paramCount(); ++k) {
    const double rms = stepJacobian_.col(k).norm() / std::sqrt(points);
    steps[k] = rms > 1e-12 ? 1.0 / rms : 0.0;
  }
  // A shape mode that barely moves the visible points must not get a step beyond its range.
  for (int k = 0; k < modeCount_; ++k) {
    const double sd = std::sqrt(std::max(shape_->variances[k], 0.0));
    double& step = steps[shapeParam(k)];
    if (step > 0.0) step = std::min(step, sd);
  }
}

void ShapeProjector::clamp(Eigen::Ref<Eigen::VectorXd> p) const {
  constexpr double kMaxAngle = 0.49 * std::numbers::pi;
  p[kParamScale] = std::max(p[kParamScale], 1e-3);
  for (const int k : {kParamPitch, kParamYaw, kParamRoll}) {
    p[k] = std::clamp(p[k], -kMaxAngle, kMaxAngle);
  }
  if (planar_) {
    p[kParamPitch] = 0.0;
    p[kParamYaw] = 0.0;
  }
  for (int k = 0; k < modeCount_; ++k) {
    const double limit = shape_->limitSd * std::sqrt(std::max(shape_->variances[k], 0.0));
    p[shapeParam(k)] = std::clamp(p[shapeParam(k)], -limit, limit);
  }
}

Eigen::Matrix2Xd projectShape(const ShapeModel& shape, const Camera& camera,
                              const FitState& state) {
  ShapeProjector projector(shape, camera);
  projector.setDepth(state.pose.translation.z());
  Eigen::Matrix2Xd points(2, shape.pointCount());
  projector.project(toParams(state), points);
  return points;
}

}  // namespace clm3d
