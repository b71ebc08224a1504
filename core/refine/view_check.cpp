#include "core/refine/view_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <optional>

#include "core/common/error.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/projection.hpp"
#include "core/geometry/similarity2.hpp"
#include "core/refine/descent_check.hpp"
#include "core/refine/descent_refinement.hpp"
#include "core/refine/detail/descent_features.hpp"

namespace clm3d {

namespace {

// The points' box size, sqrt(width height).
double boxSize(const Eigen::Matrix2Xd& points) {
  const Eigen::Vector2d extent = points.rowwise().maxCoeff() - points.rowwise().minCoeff();
  return std::sqrt(std::max(0.0, extent.x() * extent.y()));
}

}  // namespace

ViewCheck viewCheckLayout(const ClmModel& model, int view) {
  const ViewModel& v = model.views.at(static_cast<std::size_t>(view));
  if (v.mirrored) throw Error("viewCheckLayout: view " + std::to_string(view) + " is mirrored");
  ViewCheck check;
  for (int i = 0; i < static_cast<int>(v.visible.size()); ++i) {
    if (v.visible[static_cast<std::size_t>(i)]) check.landmarks.push_back(i);
  }
  // The mean shape through a camera far away, so that the view is nearly orthographic; image
  // axes as every fit's points.
  const Camera camera = Camera::fromVerticalFov(1000, 1000, kDefaultVerticalFovDeg);
  const Pose pose =
      Pose::fromDegrees(v.pitchDeg, v.yawDeg, 0.0, Eigen::Vector3d(0.0, 0.0, -5000.0));
  const Eigen::Matrix2Xd all = projectPoints(model.shape.meanShape, pose, camera);
  Eigen::Matrix2Xd seen(2, static_cast<Eigen::Index>(check.landmarks.size()));
  for (std::size_t k = 0; k < check.landmarks.size(); ++k) {
    seen.col(static_cast<Eigen::Index>(k)) = all.col(check.landmarks[k]);
  }
  const Eigen::Vector2d centre = 0.5 * (seen.rowwise().maxCoeff() + seen.rowwise().minCoeff());
  const double size = boxSize(seen);
  if (!(size > 0.0)) throw Error("viewCheckLayout: the view's mean shape has an empty box");
  check.meanShape = (seen.colwise() - centre) / size;
  check.classifier.window = kViewCheckWindow;
  return check;
}

Eigen::VectorXf viewCheckFeatures(const ClmModel& model, int view, const ViewCheck& check,
                                  const cv::Mat& image, const Eigen::Matrix2Xd& points) {
  const ViewModel& v = model.views.at(static_cast<std::size_t>(view));
  const auto k = static_cast<Eigen::Index>(check.landmarks.size());
  // A mirrored view's fit read as its mirror image: landmark i of the source is the fit's
  // mirrorOf(i), and x is flipped below with the crop.
  Eigen::Matrix2Xd read(2, k);
  std::optional<Scheme> scheme;  // parsed from the model's JSON: once, and only when mirrored
  if (v.mirrored) scheme = model.scheme();
  for (Eigen::Index j = 0; j < k; ++j) {
    const int landmark = check.landmarks[static_cast<std::size_t>(j)];
    read.col(j) = points.col(scheme ? scheme->mirrorOf(landmark) : landmark);
  }
  const double size = boxSize(read);
  if (k == 0 || !read.allFinite() || !(size > 1.0) || image.empty()) return {};
  // The crop: the points' box with a window and a half around it, at kViewCheckFacePixels.
  DescentRegion region =
      greyRegion(image, read, 1.5 * check.classifier.window * size, kViewCheckFacePixels / size);
  cv::Mat& grey = region.grey;
  Eigen::Matrix2Xd inCrop = region.toRegion(read);
  const int width = grey.cols;
  if (v.mirrored) {
    cv::flip(grey, grey, 1);
    inCrop.row(0) = (width - 1.0) - inCrop.row(0).array();
  }
  const Similarity2 frame = alignSimilarity2(check.meanShape, inCrop);
  return descentFeatures(grey, frame, frame.inverse(inCrop), check.classifier.window);
}

Eigen::VectorXf photoFitFeatures(const ClmModel& model, int view, const cv::Mat& image,
                                 const Eigen::Matrix2Xd& points) {
  if (view < 0 || view >= static_cast<int>(model.views.size())) return {};
  const int layout =
      model.photoFitLayoutView(std::abs(model.views[static_cast<std::size_t>(view)].yawDeg));
  if (layout < 0) return {};
  return viewCheckFeatures(model, view, viewCheckLayout(model, layout), image, points);
}

double viewCheckProbability(const ClmModel& model, int view, const cv::Mat& image,
                            const Eigen::Matrix2Xd& points) {
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  if (view < 0 || view >= static_cast<int>(model.views.size())) return none;
  const ViewCheck& check = model.views[static_cast<std::size_t>(view)].check;
  if (check.empty()) return none;
  const Eigen::VectorXf features = viewCheckFeatures(model, view, check, image, points);
  if (features.size() != check.classifier.weights.size()) return none;
  return checkProbability(check.classifier, features);
}

}  // namespace clm3d
