#include "core/train/report.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "core/geometry/pose.hpp"
#include "core/viz/contact_sheet.hpp"
#include "core/viz/image_file.hpp"
#include "core/viz/landmark_overlay.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

constexpr int kTile = 48;    // displayed patch size
constexpr int kLabel = 120;  // width of the view label column
constexpr int kHeader = 22;  // height of the landmark number row

std::string viewLabel(const ViewModel& view) {
  std::ostringstream label;
  label << "p" << view.pitchDeg << " y" << view.yawDeg << (view.mirrored ? " (m)" : "");
  return label.str();
}

// A patch as an 8-bit tile: stretched to its own range (grey) or 0..1 -> 0..255 (alpha).
cv::Mat patchTile(const Eigen::Ref<const Eigen::VectorXf>& patch, int size, bool stretch) {
  cv::Mat image(size, size, CV_32F);
  for (int i = 0; i < size * size; ++i) image.at<float>(i / size, i % size) = patch[i];
  double low = 0, high = 1;
  if (stretch) cv::minMaxLoc(image, &low, &high);
  cv::Mat tile8;
  image.convertTo(tile8, CV_8U, 255.0 / std::max(high - low, 1e-6),
                  -low * 255.0 / std::max(high - low, 1e-6));
  cv::Mat big;
  cv::resize(tile8, big, cv::Size(kTile, kTile), 0, 0, cv::INTER_NEAREST);
  cv::Mat bgr;
  cv::cvtColor(big, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

void putLabel(cv::Mat& image, const std::string& text, cv::Point at, double scale = 0.4) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(230, 230, 230), 1,
              cv::LINE_AA);
}

// A row per view, a column per landmark, each tile the mean grey (or alpha) patch.
cv::Mat patchGrid(const ClmModel& model, int scale, bool alpha) {
  const int n = model.shape.pointCount();
  const auto views = static_cast<int>(model.views.size());
  cv::Mat grid(kHeader + views * (kTile + 2), kLabel + n * (kTile + 2), CV_8UC3,
               cv::Scalar(48, 48, 48));
  for (int i = 0; i < n; ++i) {
    putLabel(grid, std::to_string(i + 1), {kLabel + i * (kTile + 2) + kTile / 3, kHeader - 6});
  }
  for (int v = 0; v < views; ++v) {
    const ViewModel& view = model.views[static_cast<std::size_t>(v)];
    const int top = kHeader + v * (kTile + 2);
    putLabel(grid, viewLabel(view), {4, top + kTile / 2 + 4});
    if (scale >= static_cast<int>(view.scales.size())) continue;
    const PatchModel& patches = view.scales[static_cast<std::size_t>(scale)];
    for (int i = 0; i < n; ++i) {
      const cv::Rect where(kLabel + i * (kTile + 2), top, kTile, kTile);
      const int entry = patches.entryOf(i);
      if (entry < 0) {
        grid(where).setTo(cv::Scalar(16, 16, 16));
        continue;
      }
      const cv::Mat tile =
          alpha
              ? patchTile(patches.alpha[static_cast<std::size_t>(entry)], patches.patchSize, false)
              : patchTile(patches.pca.mean.segment(patches.offsetOf(entry), patches.patchPixels()),
                          patches.patchSize, true);
      tile.copyTo(grid(where));
    }
  }
  return grid;
}

// Points (3 x n, model coordinates) rotated by (pitch, yaw) and drawn orthographically.
LandmarkSet drawnPoints(const Eigen::Matrix3Xd& shape, double pitchDeg, double yawDeg, int size) {
  const Eigen::Matrix3d rotation = Pose::fromDegrees(pitchDeg, yawDeg, 0).rotation();
  const Eigen::Matrix3Xd turned = rotation * shape;
  const Eigen::Vector3d centre = turned.rowwise().mean();
  const double extent = std::max((turned.row(0).array() - centre.x()).abs().maxCoeff(),
                                 (turned.row(1).array() - centre.y()).abs().maxCoeff());
  const double scale = 0.42 * size / std::max(extent, 1e-6);
  LandmarkSet points(static_cast<int>(shape.cols()), 2);
  for (Eigen::Index i = 0; i < shape.cols(); ++i) {
    points.set(static_cast<int>(i),
               Eigen::Vector2d(size / 2.0 + scale * (turned(0, i) - centre.x()),
                               size / 2.0 - scale * (turned(1, i) - centre.y())));
  }
  return points;
}

cv::Mat shapeTile(const Eigen::Matrix3Xd& shape, double pitchDeg, double yawDeg,
                  const std::vector<bool>& visible, const Scheme& scheme, int size) {
  cv::Mat tile(size, size, CV_8UC3, cv::Scalar(24, 24, 24));
  drawLandmarks(tile, drawnPoints(shape, pitchDeg, yawDeg, size), visible, scheme, {true, 1.0});
  return tile;
}

}  // namespace

std::vector<fs::path> writeTrainingReport(const ClmModel& model, const fs::path& folder) {
  fs::create_directories(folder);
  const Scheme scheme = model.scheme();
  std::vector<fs::path> written;
  const auto write = [&](const std::string& name, const cv::Mat& image) {
    written.push_back(folder / name);
    writeImage(written.back(), image);
  };
  int scales = 0;
  for (const ViewModel& view : model.views)
    scales = std::max(scales, static_cast<int>(view.scales.size()));
  for (int s = 0; s < scales; ++s) {
    write("mean-patches-scale" + std::to_string(s) + ".png", patchGrid(model, s, false));
    write("alpha-scale" + std::to_string(s) + ".png", patchGrid(model, s, true));
  }

  // Which landmarks each view hides: the mean shape seen from the view, hidden points hollow.
  std::vector<cv::Mat> tiles;
  std::vector<std::string> captions;
  for (const ViewModel& view : model.views) {
    tiles.push_back(
        shapeTile(model.shape.meanShape, view.pitchDeg, view.yawDeg, view.visible, scheme, 220));
    int hidden = 0;
    for (bool v : view.visible) hidden += v ? 0 : 1;
    captions.push_back(viewLabel(view) + ": " + std::to_string(hidden) + " hidden");
  }
  const int columns =
      model.views.size() == 15 ? 5 : std::min<int>(5, static_cast<int>(tiles.size()));
  write("hidden-landmarks.png", makeContactSheet(tiles, std::max(columns, 1), captions));

  // Shape modes: rows = modes, columns = -3, 0, +3 SD frontal then side.
  tiles.clear();
  captions.clear();
  const int modes = std::min(3, model.shape.modeCount());
  for (int k = 0; k < modes; ++k) {
    for (double yaw : {0.0, 90.0}) {
      for (double sd : {-3.0, 0.0, 3.0}) {
        Eigen::VectorXd b = Eigen::VectorXd::Zero(model.shape.modeCount());
        b[k] = sd * std::sqrt(model.shape.variances[k]);
        tiles.push_back(shapeTile(model.shape.shape(b), 0.0, model.shape.dims == 2 ? 0.0 : yaw, {},
                                  scheme, 220));
        std::ostringstream caption;
        caption << "mode " << k + 1 << " " << std::showpos << sd << " SD"
                << (yaw == 0 ? " front" : " side");
        captions.push_back(caption.str());
      }
    }
  }
  if (!tiles.empty()) write("shape-modes.png", makeContactSheet(tiles, 6, captions));
  return written;
}

}  // namespace clm3d
