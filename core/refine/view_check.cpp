#include "core/refine/view_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/projection.hpp"
#include "core/geometry/similarity2.hpp"
#include "core/refine/descent_check.hpp"
#include "core/refine/descent_features.hpp"

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
  for (Eigen::Index j = 0; j < k; ++j) {
    const int landmark = check.landmarks[static_cast<std::size_t>(j)];
    read.col(j) = points.col(v.mirrored ? model.scheme().mirrorOf(landmark) : landmark);
  }
  const double size = boxSize(read);
  if (k == 0 || !read.allFinite() || !(size > 1.0) || image.empty()) return {};
  // The crop: the points' box with a window and a half around it, at kViewCheckFacePixels.
  const double margin = 1.5 * kViewCheckWindow * size;
  const Eigen::Vector2d low = read.rowwise().minCoeff().array() - margin;
  const Eigen::Vector2d high = read.rowwise().maxCoeff().array() + margin;
  const auto clampTo = [](double value, int lo, int hi) {
    return static_cast<int>(std::clamp(value, static_cast<double>(lo), static_cast<double>(hi)));
  };
  const int x0 = clampTo(std::floor(low.x()), 0, image.cols - 1);
  const int y0 = clampTo(std::floor(low.y()), 0, image.rows - 1);
  const int x1 = clampTo(std::ceil(high.x()) + 1, x0 + 1, image.cols);
  const int y1 = clampTo(std::ceil(high.y()) + 1, y0 + 1, image.rows);
  cv::Mat part = image(cv::Rect(x0, y0, x1 - x0, y1 - y0));
  if (part.type() == CV_8UC3) {
    cv::cvtColor(part, part, cv::COLOR_BGR2GRAY);
  } else if (part.type() == CV_8UC4) {
    cv::cvtColor(part, part, cv::COLOR_BGRA2GRAY);
  } else if (part.type() != CV_8UC1 && part.type() != CV_32FC1) {
    throw InputError("view check: unsupported image type (need 8-bit grey, BGR or BGRA, or float)");
  }
  const double scale = kViewCheckFacePixels / size;
  const int width = std::max(1, static_cast<int>(std::lround(part.cols * scale)));
  const int height = std::max(1, static_cast<int>(std::lround(part.rows * scale)));
  cv::Mat resized;
  cv::resize(part, resized, cv::Size(width, height), 0, 0,
             scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
  cv::Mat grey;
  resized.convertTo(grey, CV_32F, part.depth() == CV_8U ? 1.0 / 255.0 : 1.0);
  Eigen::Matrix2Xd inCrop(2, k);
  for (Eigen::Index j = 0; j < k; ++j) {
    inCrop.col(j) =
        (read.col(j) - Eigen::Vector2d(x0, y0)) * (static_cast<double>(width) / part.cols);
  }
  if (v.mirrored) {
    cv::flip(grey, grey, 1);
    inCrop.row(0) = (width - 1.0) - inCrop.row(0).array();
  }
  const Similarity2 frame = alignSimilarity2(check.meanShape, inCrop);
  return descentFeatures(grey, frame, frame.inverse(inCrop), check.classifier.window);
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
