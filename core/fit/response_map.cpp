#include "core/fit/response_map.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"

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
  // Destination (u, v) -> source: centre + Rot (u - half, v - half).
  const cv::Matx23d map(c, s, centre.x() - c * half - s * half,  //
                        -s, c, centre.y() + s * half - c * half);
  cv::warpAffine(image, out, map, cv::Size(size, size), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                 cv::BORDER_REPLICATE);
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
  // window scores 0, as normalisePatch makes it zeros. Window sums from integral images, the dot
  // products directly: 9 x 9 windows of 20 x 20 cost about 32 000 multiply-adds per unit.
  const int rows = region.rows - patchSize + 1;
  const int cols = region.cols - patchSize + 1;
  thread_local cv::Mat sum;  // scratch: this runs per landmark and iteration of every frame
  thread_local cv::Mat squares;
  cv::integral(region, sum, squares, CV_64F, CV_64F);
  scores.create(rows, cols, CV_32FC(units));
  using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const Eigen::VectorXf weightSums = expert.weights.colwise().sum().transpose();
  const double n = pixels;
  for (int y = 0; y < rows; ++y) {
    auto* out = scores.ptr<float>(y);
    for (int x = 0; x < cols; ++x, out += units) {
      const auto boxSum = [&](const cv::Mat& table) {
        return table.at<double>(y + patchSize, x + patchSize) - table.at<double>(y, x + patchSize) -
               table.at<double>(y + patchSize, x) + table.at<double>(y, x);
      };
      const double mean = boxSum(sum) / n;
      const double variance = boxSum(squares) / n - mean * mean;
      if (!(variance > 1e-12)) {
        std::fill(out, out + units, 0.0f);
        continue;
      }
      const double inverseSd = 1.0 / std::sqrt(variance);
      const Eigen::Map<const RowMajor, 0, Eigen::OuterStride<>> window(
          region.ptr<float>(y) + x, patchSize, patchSize, Eigen::OuterStride<>(region.cols));
      for (int k = 0; k < units; ++k) {
        const Eigen::Map<const RowMajor> weights(expert.weights.col(k).data(), patchSize,
                                                 patchSize);
        const double dot = window.cwiseProduct(weights).sum();
        out[k] = static_cast<float>((dot - mean * weightSums[k]) * inverseSd);
      }
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
