#include "core/fit/response_map.hpp"

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
  if (expert.weights.size() != pixels || region.type() != CV_32FC1 || region.rows < patchSize ||
      region.cols < patchSize) {
    throw Error("expertScores: region or weights do not match the patch size");
  }
  // w . n(x) = sum w (x - mean) / sd_population = CCOEFF_NORMED * |w| * sqrt(N) for zero-mean w.
  const cv::Mat weights(patchSize, patchSize, CV_32FC1, const_cast<float*>(expert.weights.data()));
  cv::matchTemplate(region, weights, scores, cv::TM_CCOEFF_NORMED);
  scores *= static_cast<double>(expert.weights.norm()) * std::sqrt(static_cast<double>(pixels));
}

void expertResponse(const cv::Mat& region, const PatchExpert& expert, int patchSize,
                    cv::Mat& response) {
  expertScores(region, expert, patchSize, response);
  for (int r = 0; r < response.rows; ++r) {
    auto* row = response.ptr<float>(r);
    for (int c = 0; c < response.cols; ++c) row[c] = expert.response(row[c]);
  }
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
  const Eigen::Vector2d a0 = upright.rowwise().mean();
  const Eigen::Vector2d b0 = turned.rowwise().mean();
  double dot = 0.0;
  double cross = 0.0;
  for (int k = 0; k < m; ++k) {
    const Eigen::Vector2d a = upright.col(k) - a0;
    const Eigen::Vector2d b = turned.col(k) - b0;
    dot += a.dot(b);
    cross += a.x() * b.y() - a.y() * b.x();
  }
  // cross > 0 turns +x towards +y: clockwise on screen, the opposite of sampleRegion's angle.
  return -std::atan2(cross, dot);
}

double meanExpertResponse(const cv::Mat& image, const ShapeProjector& projector,
                          const std::vector<PatchExpert>& experts, int patchSize,
                          const Eigen::Ref<const Eigen::VectorXd>& p) {
  const int m = projector.landmarkCount();
  if (m == 0 || static_cast<int>(experts.size()) != m) return 0.0;
  Eigen::Matrix2Xd points(2, m);
  projector.project(p, points);
  const double angle = faceInPlaneAngle(projector, p);
  cv::Mat region;
  cv::Mat response;
  double sum = 0.0;
  for (int k = 0; k < m; ++k) {
    sampleRegion(image, points.col(k), angle, patchSize, region);
    expertResponse(region, experts[static_cast<std::size_t>(k)], patchSize, response);
    sum += response.at<float>(0, 0);
  }
  return sum / m;
}

}  // namespace clm3d
