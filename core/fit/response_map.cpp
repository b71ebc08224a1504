#include "core/fit/response_map.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/common/error.hpp"
#include "core/fit/detail/window_dots.hpp"
#include "core/image/patch_sampling.hpp"

namespace clm3d {

Eigen::Vector2d rotateOffset(const Eigen::Vector2d& offset, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return {c * offset.x() + s * offset.y(), -s * offset.x() + c * offset.y()};
}

void sampleRegion(const cv::Mat& image, const Eigen::Vector2d& centre, double angle, int size,
                  cv::Mat& out) {
  if (image.type() != CV_32FC1 || image.empty() || size < 1) {
    throw Error("sampleRegion: needs a non-empty CV_32FC1 image and a positive size");
  }
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  const double half = (size - 1) / 2.0;
  // Region pixel (u, v) -> image: origin + u (c, -s) + v (s, c). Sampled here rather than with
  // cv::warpAffine, whose set-up cost dominated for these small regions (a quarter of a frame's
  // search), and in floating point rather than its 1/32-pixel fixed point.
  const double originX = centre.x() - c * half - s * half;
  const double originY = centre.y() + s * half - c * half;
  out.create(size, size, CV_32FC1);
  // The region's corners bound its samples; inside the image with a pixel to spare (and a margin
  // for the float positions below), no sample needs the border.
  double lowX = originX, highX = originX, lowY = originY, highY = originY;
  for (const double u : {0.0, size - 1.0}) {
    for (const double v : {0.0, size - 1.0}) {
      const double x = originX + u * c + v * s;
      const double y = originY - u * s + v * c;
      lowX = std::min(lowX, x), highX = std::max(highX, x);
      lowY = std::min(lowY, y), highY = std::max(highY, y);
    }
  }
  const bool inside =
      lowX >= 0.0 && lowY >= 0.0 && highX < image.cols - 1.01 && highY < image.rows - 1.01;
  const std::size_t step = image.step1();
  const float* pixels = image.ptr<float>(0);
  // Positions in float from each row's start: a region spans a few dozen pixels, so the rounding
  // stays far below a thousandth of a pixel. First every sample's top-left pixel and weights, a
  // loop the compiler vectorises, then the interpolation.
  const auto stepX = static_cast<float>(c);
  const auto stepY = static_cast<float>(-s);
  thread_local std::vector<float> scratchX;
  thread_local std::vector<float> scratchY;
  thread_local std::vector<int> scratchColumns;
  thread_local std::vector<int> scratchRows;
  scratchX.resize(static_cast<std::size_t>(size));
  scratchY.resize(scratchX.size());
  scratchColumns.resize(scratchX.size());
  scratchRows.resize(scratchX.size());
  // Not aliased by the region's rows, so the compiler may keep them in registers and vectorise.
  float* __restrict weightX = scratchX.data();
  float* __restrict weightY = scratchY.data();
  int* __restrict columns = scratchColumns.data();
  int* __restrict rowsAt = scratchRows.data();
  for (int v = 0; v < size; ++v) {
    float* __restrict row = out.ptr<float>(v);
    const auto rowX = static_cast<float>(originX + v * s);
    const auto rowY = static_cast<float>(originY + v * c);
    if (inside) {
      for (int u = 0; u < size; ++u) {
        const float x = rowX + static_cast<float>(u) * stepX;
        const float y = rowY + static_cast<float>(u) * stepY;
        const int x0 = static_cast<int>(x);  // x, y >= 0: truncation is the floor
        const int y0 = static_cast<int>(y);
        weightX[u] = x - static_cast<float>(x0);
        weightY[u] = y - static_cast<float>(y0);
        columns[u] = x0;
        rowsAt[u] = y0;
      }
      for (int u = 0; u < size; ++u) {
        const float* top = pixels + static_cast<std::size_t>(rowsAt[u]) * step + columns[u];
        const float* bottom = top + step;
        const float upper = top[0] + weightX[u] * (top[1] - top[0]);
        const float lower = bottom[0] + weightX[u] * (bottom[1] - bottom[0]);
        row[u] = upper + weightY[u] * (lower - upper);
      }
      continue;
    }
    // Near the border (rare): samplePatch's clamped sampler, the border pixels repeated.
    for (int u = 0; u < size; ++u) {
      row[u] = sampleBilinear(image, originX + u * c + v * s, originY - u * s + v * c);
    }
  }
}

void expertScores(const cv::Mat& region, const PatchExpert& expert, int patchSize,
                  cv::Mat& scores) {
  const int pixels = patchSize * patchSize;
  const int units = expert.units();
  if (expert.weights.rows() != pixels || units < 1 || units > CV_CN_MAX ||
      region.type() != CV_32FC1 || region.rows < patchSize || region.cols < patchSize ||
      !region.isContinuous()) {
    throw Error("expertScores: region or weights do not match the patch size");
  }
  // w . n(x) = (w . x - mean(x) sum(w)) / sd(x), sd the population SD (normalisePatch); a flat
  // window scores 0, as normalisePatch makes it zeros.
  const int rows = region.rows - patchSize + 1;
  const int cols = region.cols - patchSize + 1;
  thread_local std::vector<double> mean;  // scratch: this runs per landmark and iteration
  thread_local std::vector<double> variance;
  windowMoments(region, patchSize, mean, variance);
  if (!scores.isContinuous()) scores.release();
  scores.create(rows, cols, CV_32FC(units));
  auto* out = scores.ptr<float>(0);
  windowDots(region, expert.weights, patchSize, out);
  thread_local Eigen::VectorXf weightSums;  // the same sums, into a buffer kept between calls
  weightSums.resize(units);
  weightSums.noalias() = expert.weights.colwise().sum().transpose();
  for (std::size_t w = 0; w < mean.size(); ++w, out += units) {
    if (!(variance[w] > 1e-12)) {
      std::fill(out, out + units, 0.0f);
      continue;
    }
    const double inverseSd = 1.0 / std::sqrt(variance[w]);
    for (int k = 0; k < units; ++k) {
      out[k] = static_cast<float>((out[k] - mean[w] * weightSums[k]) * inverseSd);
    }
  }
}

void expertResponse(const cv::Mat& region, const PatchExpert& expert, int patchSize,
                    cv::Mat& response) {
  thread_local cv::Mat scores;
  expertScores(region, expert, patchSize, scores);
  const int units = expert.units();
  response.create(scores.rows, scores.cols, CV_32FC1);
  for (int r = 0; r < response.rows; ++r) {
    const auto* in = scores.ptr<float>(r);
    auto* row = response.ptr<float>(r);
    for (int c = 0; c < response.cols; ++c) row[c] = expert.response(in + c * units);
  }
}

double inPlaneRotation(const Eigen::Matrix2Xd& upright, const Eigen::Matrix2Xd& turned) {
  const Eigen::Vector2d a0 = upright.rowwise().mean();
  const Eigen::Vector2d b0 = turned.rowwise().mean();
  double dot = 0.0;
  double cross = 0.0;
  for (Eigen::Index k = 0; k < upright.cols(); ++k) {
    const Eigen::Vector2d a = upright.col(k) - a0;
    const Eigen::Vector2d b = turned.col(k) - b0;
    dot += a.dot(b);
    cross += a.x() * b.y() - a.y() * b.x();
  }
  // cross > 0 turns +x towards +y: clockwise on screen, the opposite of sampleRegion's angle.
  return -std::atan2(cross, dot);
}

double faceInPlaneAngle(const ShapeProjector& projector,
                        const Eigen::Ref<const Eigen::VectorXd>& p) {
  const int m = projector.landmarkCount();
  if (m < 2) return 0.0;
  Eigen::Matrix2Xd turned(2, m);
  Eigen::Matrix2Xd upright(2, m);
  projector.project(p, turned);
  Eigen::VectorXd unrolled = p;
  unrolled[kParamRoll] = 0.0;
  projector.project(unrolled, upright);
  return inPlaneRotation(upright, turned);
}

double expertResponses(const cv::Mat& image, const ShapeProjector& projector,
                       const std::vector<PatchExpert>& experts, int patchSize,
                       const Eigen::Ref<const Eigen::VectorXd>& p, Eigen::VectorXd& responses) {
  const int m = projector.landmarkCount();
  responses.setZero(m);
  if (m == 0 || static_cast<int>(experts.size()) != m) return 0.0;
  Eigen::Matrix2Xd points(2, m);
  projector.project(p, points);
  const double angle = faceInPlaneAngle(projector, p);
  cv::Mat region;
  cv::Mat response;
  for (int k = 0; k < m; ++k) {
    sampleRegion(image, points.col(k), angle, patchSize, region);
    expertResponse(region, experts[static_cast<std::size_t>(k)], patchSize, response);
    responses[k] = response.at<float>(0, 0);
  }
  return responses.mean();
}

}  // namespace clm3d
