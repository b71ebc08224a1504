#include "core/detect/initialisation.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <string>

#include "core/fit/shape_projector.hpp"
#include "core/geometry/similarity2.hpp"

namespace clm3d {

namespace {

// Box calibration: how each detector's boxes sit on faces, as (eye distance / box width, eye
// midpoint - box centre in box widths x and y, |yaw| of profile starts); docs/initialisation.md
// has the tables.
//
// Frontal boxes: measured on the 805 LFPW training photos (../shared/data/photos/lfpw/train) by
//   clm3d detect --images lfpw/train --calibrate --calibrate-to mean-shape
//       --model <the test fixture model: procedural heads 1-4> --out train-mean.json
// as the medians over the annotated faces' frontal boxes on faces within 15 degrees of frontal,
// measured against the model's mean shape fitted (pose and depth only) to thesis points 1-18 and
// 22 of each mark-up: the box-to-face relation that places the mean shape best. Measured:
//   cascade frontal  655 faces  0.3775 -0.0002 -0.1194  (eye centres: 0.394 +0.002 -0.105)
//   dlib frontal     464 faces  0.4256 -0.0068 -0.2427  (eye centres: 0.444 -0.004 -0.224)
// On the 224 LFPW test photos the start error (mean distance over thesis points 1-18 and 22 / true
// eye distance, the annotated face's box, --min-face 80) fell from 0.153 to 0.147 (cascade) and
// from 0.198 to 0.181 (dlib) against the render-measured constants that were here before
// (cascade 0.381 -0.012 -0.116, dlib 0.447 -0.028 -0.245); the eye-centre medians gave 0.164 and
// 0.191.
//
// Profile boxes: still the render figures of tests/unit/detect/box_calibration_test.cpp (P:
// procedural heads 11-14 and J: the james scan at yaw -75..75, pitch -15/0/15, 640x480, 45-degree
// camera; the mean of the two medians):
//   cascade profile  P 0.320 -0.174 -0.068 45  J 0.297 -0.161 -0.064 45
//   dlib side        P 0.395 -0.024 -0.175 30  J 0.436 -0.031 -0.168 45  (R 0.397 -0.020 -0.168 30)
// On LFPW the profile boxes fire mostly on near-frontal faces (median |yaw| 13 cascade, 11 dlib:
// cascade 0.294 -0.153 -0.083, dlib 0.394 -0.014 -0.171 against the mean shape), which is not
// the population of turned faces those boxes exist for, so the photos' figures are not used.
constexpr BoxCalibration kCascadeFrontal{0.3775, -0.0002, -0.1194, 0.0};
constexpr BoxCalibration kCascadeProfile{0.309, -0.168, -0.066, 45.0};
constexpr BoxCalibration kDlibFrontal{0.4256, -0.0068, -0.2427, 0.0};
constexpr BoxCalibration kDlibProfile{0.409, -0.025, -0.170, 35.0};

// The cascade's profile boxes on real turned faces: a second placement (turnedFaceCalibration),
// measured on every 4th face of the AFLW training split (2,148 faces, 1,242 profile boxes on the
// annotated face) by
//   clm3d detect --images LIST --detector cascade --calibrate --calibrate-to mean-shape
//       --model <the model of resources/datasets/real.json> --poses aflw21/index.csv
// (the mean shape fitted to each face's visible points): 0.497 -0.153 -0.203, yaw 49, spread
// 0.13 / 0.14 / 0.14; on its faces at |yaw| 30-90 alone 0.505 -0.153 -0.218, yaw 52. A real
// profile face fills more of the box than a rendered one and sits lower in it. The yaw is 40, not
// the median 49, chosen on 600 other training faces (200 drawn per |yaw| band): with every
// profile box so placed, starts at 40 fitted 67 of the faces at |yaw| 60-90 right (error under
// 0.08 of the face box) where 49 fitted 61, and 175 against 173 at 0-30 (docs/initialisation.md).
constexpr BoxCalibration kCascadeTurnedFace{0.497, -0.153, -0.203, 40.0};

// The weak prior on log(scale) that settles the depth where perspective does not (SD 0.3).
constexpr double kLogScaleSd = 0.3;

std::vector<double> startingYaws(bool planar) {
  if (planar) return {0.0};
  return {-60.0, -40.0, -20.0, 0.0, 20.0, 40.0, 60.0};
}

double meanFocal(const Camera& camera) {
  return 0.5 * (camera.focalX() + camera.focalY());
}

// Levenberg-Marquardt on the reprojection error of the present points, with the shape prior and,
// for the 3D model, the depth as an extra unknown u = log(-Tz).
class PointsProblem {
 public:
  // depthUnknown: the 3D model's depth is estimated too (else it stays where setDepth put it).
  PointsProblem(const ShapeModel& shape, const Camera& camera, const std::vector<int>& landmarks,
                const Eigen::Matrix2Xd& target, double sigma, bool depthUnknown = true)
      : shape_(shape),
        projector_(shape, camera),
        target_(target),
        sigma2_(sigma * sigma),
        withDepth_(depthUnknown && !projector_.planar()),
        params_(projector_.paramCount()),
        unknowns_(params_ + (withDepth_ ? 1 : 0)),
        points_(2, static_cast<Eigen::Index>(landmarks.size())),
        jacobian_(2 * static_cast<Eigen::Index>(landmarks.size()), params_) {
    projector_.setLandmarks(landmarks);
    projector_.setInputPixels();
    radius_ = shape.meanShape.colwise().norm().maxCoeff();
  }

  int unknowns() const { return unknowns_; }
  int params() const { return params_; }
  bool withDepth() const { return withDepth_; }
  ShapeProjector& projector() { return projector_; }

  // Energy at x (p, then u for the 3D model); +inf when part of the face would be behind the
  // camera.
  double energy(const Eigen::VectorXd& x) {
    if (!setDepth(x)) return std::numeric_limits<double>::infinity();
    projector_.project(x.head(params_), points_);
    return (points_ - target_).squaredNorm() + priorEnergy(x);
  }

  // Gauss-Newton normal equations at x: H = J^T J + prior, g = J^T r + prior gradient.
  void linearise(const Eigen::VectorXd& x, Eigen::MatrixXd& h, Eigen::VectorXd& g) {
    setDepth(x);
    projector_.jacobian(x.head(params_), jacobian_, &points_);
    const Eigen::Map<const Eigen::VectorXd> residual(points_.data(), points_.size());
    const Eigen::Map<const Eigen::VectorXd> target(target_.data(), target_.size());
    Eigen::MatrixXd j(jacobian_.rows(), unknowns_);
    j.leftCols(params_) = jacobian_;
    if (withDepth_) {
      // d(points)/du by central differences (the projector keeps Tz outside p).
      const double step = 1e-6;
      Eigen::VectorXd shifted = x;
      Eigen::Matrix2Xd plus(points_.rows(), points_.cols());
      Eigen::Matrix2Xd minus(points_.rows(), points_.cols());
      shifted[params_] = x[params_] + step;
      setDepth(shifted);
      projector_.project(x.head(params_), plus);
      shifted[params_] = x[params_] - step;
      setDepth(shifted);
      projector_.project(x.head(params_), minus);
      setDepth(x);
      const Eigen::Matrix2Xd d = (plus - minus) / (2.0 * step);
      j.col(params_) = Eigen::Map<const Eigen::VectorXd>(d.data(), d.size());
    }
    const Eigen::VectorXd r = residual - target;
    h = j.transpose() * j;
    g = j.transpose() * r;
    const int modes = shape_.modeCount();
    for (int k = 0; k < modes; ++k) {
      const double w = sigma2_ / std::max(shape_.variances[k], 1e-12);
      h(shapeParam(k), shapeParam(k)) += w;
      g[shapeParam(k)] += w * x[shapeParam(k)];
    }
    if (withDepth_) {
      // Residual rho = sigma log(S) / sd, d rho / dS = sigma / (sd S).
      const double scale = x[kParamScale];
      const double rho = std::sqrt(sigma2_) * std::log(scale) / kLogScaleSd;
      const double d = std::sqrt(sigma2_) / (kLogScaleSd * scale);
      h(kParamScale, kParamScale) += d * d;
      g[kParamScale] += d * rho;
    }
  }

  // Minimises from x in place; returns the final energy.
  double minimise(Eigen::VectorXd& x, int maxIterations) {
    projector_.clamp(x.head(params_));
    double e = energy(x);
    if (!std::isfinite(e)) return e;
    double mu = 1e-3;
    Eigen::MatrixXd h;
    Eigen::VectorXd g;
    for (int iteration = 0; iteration < maxIterations; ++iteration) {
      linearise(x, h, g);
      const double largest = std::max(h.diagonal().maxCoeff(), 1e-12);
      bool accepted = false;
      double decrease = 0.0;
      while (mu < 1e12) {
        Eigen::MatrixXd damped = h;
        damped.diagonal().array() += mu * h.diagonal().array() + 1e-12 * largest;
        const Eigen::VectorXd delta = damped.ldlt().solve(-g);
        Eigen::VectorXd candidate = x + delta;
        projector_.clamp(candidate.head(params_));
        const double ec = energy(candidate);
        if (std::isfinite(ec) && ec < e) {
          decrease = e - ec;
          x = candidate;
          e = ec;
          mu = std::max(mu / 3.0, 1e-9);
          accepted = true;
          break;
        }
        mu *= 5.0;
      }
      if (!accepted || decrease <= 1e-14 * (1.0 + e)) break;
    }
    setDepth(x);
    return e;
  }

 private:
  bool setDepth(const Eigen::VectorXd& x) {
    if (!withDepth_) return true;
    const double depth = std::exp(x[params_]);
    projector_.setDepth(-depth);
    return std::isfinite(depth) && depth > 1.5 * radius_ * std::abs(x[kParamScale]);
  }

  double priorEnergy(const Eigen::VectorXd& x) const {
    double e = 0.0;
    for (int k = 0; k < shape_.modeCount(); ++k) {
      const double b = x[shapeParam(k)];
      e += sigma2_ * b * b / std::max(shape_.variances[k], 1e-12);
    }
    if (withDepth_) {
      const double logScale = std::log(x[kParamScale]) / kLogScaleSd;
      e += sigma2_ * logScale * logScale;
    }
    return e;
  }

  const ShapeModel& shape_;
  ShapeProjector projector_;
  Eigen::Matrix2Xd target_;
  double sigma2_;
  bool withDepth_;
  int params_;
  int unknowns_;
  double radius_ = 1.0;
  Eigen::Matrix2Xd points_;
  Eigen::MatrixXd jacobian_;
};

void checkShapeSize(const ClmModel& model, const FitState& state) {
  if (state.shape.size() != model.shape.modeCount()) {
    throw InputError("initialisation: the state has " + std::to_string(state.shape.size()) +
                     " shape coefficients, the model " + std::to_string(model.shape.modeCount()));
  }
}

}  // namespace

BoxCalibration boxCalibration(DetectorKind detector, bool profile) {
  if (detector == DetectorKind::DlibHog) return profile ? kDlibProfile : kDlibFrontal;
  return profile ? kCascadeProfile : kCascadeFrontal;
}

std::optional<BoxCalibration> turnedFaceCalibration(const FaceBox& box) {
  if (!box.profile || box.detector != DetectorKind::Cascade) return std::nullopt;
  return kCascadeTurnedFace;
}

FitState stateFromBox(const ClmModel& model, const Camera& camera, const FaceBox& box) {
  return stateFromBox(model, camera, box, boxCalibration(box.detector, box.profile));
}

FitState stateFromBox(const ClmModel& model, const Camera& camera, const FaceBox& box,
                      const BoxCalibration& calibration) {
  const cv::Rect2d& r = box.box;
  if (!(std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.width) &&
        std::isfinite(r.height) && r.width > 0.0 && r.height > 0.0 && std::isfinite(box.rollDeg))) {
    throw InputError("initialisation: the face box is empty or not finite");
  }
  if (!(calibration.iodPerWidth > 0.0 && std::isfinite(calibration.iodPerWidth))) {
    throw InputError("initialisation: the box calibration's iodPerWidth must be > 0");
  }
  const ShapeModel& shape = model.shape;
  const auto [eyeA, eyeB] = model.scheme().normalisationPair();
  const Eigen::Vector3d left = shape.meanShape.col(eyeA);
  const Eigen::Vector3d right = shape.meanShape.col(eyeB);
  const double iodModel = (left - right).norm();
  if (!(iodModel > 0.0)) throw InputError("initialisation: the model's eye centres coincide");

  const double side = box.mirrored ? 1.0 : -1.0;  // yaw sign of a profile box
  const bool planar = shape.dims == 2;
  const double profileYaw = box.profile ? side * radians(calibration.yawDeg) : 0.0;

  FitState state;
  state.shape = Eigen::VectorXd::Zero(shape.modeCount());
  state.pose.scale = 1.0;
  state.pose.pitch = 0.0;
  state.pose.roll = radians(box.rollDeg);
  state.pose.yaw = planar ? 0.0 : profileYaw;

  // Frontal eye distance wanted in pixels; the planar model sees the foreshortened one.
  double iodPixels = calibration.iodPerWidth * r.width;
  if (planar) iodPixels *= std::cos(profileYaw);
  const double depth = meanFocal(camera) * iodModel / iodPixels;  // of the eye midpoint

  // The eye midpoint's calibrated offset from the box centre, turned with the face (a positive
  // roll turns counter-clockwise on the screen, y down).
  const Eigen::Vector2d offset((box.mirrored ? -1.0 : 1.0) * calibration.eyeOffsetX * r.width,
                               calibration.eyeOffsetY * r.width);
  const double c = std::cos(state.pose.roll);
  const double s = std::sin(state.pose.roll);
  const Eigen::Vector2d target =
      Eigen::Vector2d(r.x + 0.5 * r.width, r.y + 0.5 * r.height) +
      Eigen::Vector2d(c * offset.x() + s * offset.y(), -s * offset.x() + c * offset.y());
  const Eigen::Vector3d mid = state.pose.rotation() * (0.5 * (left + right));
  // Eye midpoint at `depth` along -z, on the ray through `target`.
  const Eigen::Vector3d eye = camera.pixelToEye(target, depth + mid.z());
  state.pose.translation = eye - mid;
  return state;
}

namespace {

// The landmarks `present` marks (all when empty), checked: finite, at least 4, not all in one
// place. Their points and mean-shape positions go to target and mean.
std::vector<int> pointsToFit(const ShapeModel& shape, const Eigen::Matrix2Xd& points,
                             const std::vector<bool>& present, const PointsFitSettings& settings,
                             Eigen::Matrix2Xd& target, Eigen::Matrix3Xd& mean) {
  const int n = shape.pointCount();
  if (points.cols() != n) {
    throw InputError("initial points: " + std::to_string(points.cols()) +
                     " points given, the model's scheme has " + std::to_string(n));
  }
  if (!present.empty() && static_cast<int>(present.size()) != n) {
    throw InputError("initial points: the present-point mask has " +
                     std::to_string(present.size()) + " entries, expected " + std::to_string(n));
  }
  if (!(settings.pointSigmaPixels > 0.0) || settings.maxIterations < 1) {
    throw InputError("initial points: pointSigmaPixels must be > 0 and maxIterations >= 1");
  }
  std::vector<int> used;
  for (int i = 0; i < n; ++i) {
    if (!present.empty() && !present[static_cast<std::size_t>(i)]) continue;
    if (!points.col(i).allFinite()) {
      throw InputError("initial points: point " + std::to_string(i + 1) +
                       " is marked present but is not finite");
    }
    used.push_back(i);
  }
  if (used.size() < 4) {
    throw InputError("initial points: " + std::to_string(used.size()) +
                     " points present, at least 4 are needed to place the model");
  }
  const int m = static_cast<int>(used.size());
  target.resize(2, m);
  mean.resize(3, m);
  for (int j = 0; j < m; ++j) {
    target.col(j) = points.col(used[static_cast<std::size_t>(j)]);
    mean.col(j) = shape.meanShape.col(used[static_cast<std::size_t>(j)]);
  }
  const Eigen::Vector2d spread = (target.colwise() - target.rowwise().mean()).rowwise().norm();
  if (!(spread.norm() > 1e-6)) {
    throw InputError("initial points: the present points all coincide");
  }

  return used;
}

}  // namespace

FitState stateFromPoints(const ClmModel& model, const Camera& camera,
                         const Eigen::Matrix2Xd& points, const std::vector<bool>& present,
                         const PointsFitSettings& settings) {
  const ShapeModel& shape = model.shape;
  Eigen::Matrix2Xd target;
  Eigen::Matrix3Xd mean;
  const std::vector<int> used = pointsToFit(shape, points, present, settings, target, mean);
  const int m = static_cast<int>(used.size());

  PointsProblem problem(shape, camera, used, target, settings.pointSigmaPixels);
  const bool planar = problem.projector().planar();
  const double focal = meanFocal(camera);

  Eigen::VectorXd best;
  double bestEnergy = std::numeric_limits<double>::infinity();
  for (const double yawDeg : startingYaws(planar)) {
    // Similarity of the yawed mean shape's (x, -y) to the points: roll, pixel scale, origin.
    const Eigen::Matrix3d turn = Pose::fromDegrees(0.0, yawDeg, 0.0).rotation();
    const Eigen::Matrix3Xd turned = turn * mean;
    Eigen::Matrix2Xd source(2, m);
    source.row(0) = turned.row(0);
    source.row(1) = -turned.row(1);
    const Similarity2 similarity = alignSimilarity2(source, target);
    if (!(similarity.scale > 0.0)) continue;
    const double depth = focal / similarity.scale;
    const Eigen::Vector3d origin = camera.pixelToEye(similarity.translation, depth);

    Eigen::VectorXd x = Eigen::VectorXd::Zero(problem.unknowns());
    x[kParamTx] = origin.x();
    x[kParamTy] = origin.y();
    x[kParamScale] = 1.0;
    x[kParamYaw] = radians(yawDeg);
    x[kParamRoll] = -similarity.angle;  // image rotation is clockwise for positive angle (y down)
    if (problem.withDepth())
      x[problem.params()] = std::log(depth);
    else
      problem.projector().setDepth(-depth);
    const double e = problem.minimise(x, settings.maxIterations);
    if (e < bestEnergy) {
      bestEnergy = e;
      best = x;
    }
  }
  if (best.size() == 0) throw InputError("initial points: the points do not determine a pose");

  FitState state;
  state.shape = Eigen::VectorXd::Zero(shape.modeCount());
  if (problem.withDepth()) {
    state.pose.translation.z() = -std::exp(best[problem.params()]);
  } else {
    // Planar: the depth of the only start (scale 1 there).
    state.pose.translation.z() = problem.projector().depth();
  }
  fromParams(best.head(problem.params()), state);
  return state;
}

FitState stateNearPoints(const ClmModel& model, const Camera& camera,
                         const Eigen::Matrix2Xd& points, const std::vector<bool>& present,
                         const FitState& start, const PointsFitSettings& settings) {
  checkShapeSize(model, start);
  Eigen::Matrix2Xd target;
  Eigen::Matrix3Xd mean;
  const std::vector<int> used = pointsToFit(model.shape, points, present, settings, target, mean);
  PointsProblem problem(model.shape, camera, used, target, settings.pointSigmaPixels, false);
  problem.projector().setDepth(start.pose.translation.z());
  Eigen::VectorXd x = toParams(start);
  problem.minimise(x, settings.maxIterations);
  FitState state = start;
  fromParams(x, state);
  return state;
}

Eigen::Matrix2Xd projectState(const ClmModel& model, const Camera& camera, const FitState& state) {
  checkShapeSize(model, state);
  return projectShape(model.shape, camera, state);
}

FitState initialiseFromImage(const ClmModel& model, const Camera& camera, const cv::Mat& image,
                             FaceDetector& detector) {
  if (image.cols != camera.width || image.rows != camera.height) {
    throw InputError("initialisation: the image is " + std::to_string(image.cols) + "x" +
                     std::to_string(image.rows) + ", the camera " + std::to_string(camera.width) +
                     "x" + std::to_string(camera.height));
  }
  const std::vector<FaceBox> faces = detector.detect(image);
  if (faces.empty()) {
    throw NoFaceFound(std::string("no face found by the ") + detectorKindName(detector.kind()) +
                      " face detector (smallest face searched: " +
                      std::to_string(detector.settings().minFaceSize) + " pixels)");
  }
  return stateFromBox(model, camera, faces.front());
}

}  // namespace clm3d
