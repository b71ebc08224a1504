#include "core/train/training_sample.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/fit/response_map.hpp"
#include "core/geometry/projection.hpp"
#include "core/image/patch_sampling.hpp"
#include "core/image/pyramid.hpp"
#include "core/model/texture_model.hpp"
#include "core/train/detail/cast_shadow.hpp"

namespace clm3d {
namespace {

constexpr std::uint64_t kAugmentationStream = 0xA0637E57ull;

// The landmarks' centroid and a radius that holds the whole head (twice the farthest landmark).
std::pair<Eigen::Vector3d, double> headSphere(const LandmarkSet& landmarks) {
  const Eigen::Vector3d centroid = landmarks.centroid();
  double farthest = 0.0;
  for (int i = 0; i < landmarks.size(); ++i) {
    if (landmarks.has(i)) farthest = std::max(farthest, (landmarks.point(i) - centroid).norm());
  }
  return {centroid, 2.0 * farthest};
}

// Distance from `centre` to the nearest different entry of `centres` (0 when there is none).
double nearestOtherCentre(const std::vector<double>& centres, double centre) {
  double nearest = 0.0;
  for (double c : centres) {
    const double d = std::abs(c - centre);
    if (d > 1e-9 && (nearest == 0.0 || d < nearest)) nearest = d;
  }
  return nearest;
}

}  // namespace

SampleSpec drawSample(const TrainSettings& settings, const ViewCentre& view, std::uint64_t seed,
                      int subject, int viewIndex, int sample) {
  const std::uint64_t key = mixKey(mixKey(mixKey(seed, static_cast<std::uint64_t>(subject)),
                                          static_cast<std::uint64_t>(viewIndex)),
                                   static_cast<std::uint64_t>(sample));
  SplitMixRandom random(key);
  const PerturbationSettings& p = settings.perturbation;
  SampleSpec spec;
  const auto range = [&](const std::vector<double>& centres, double centre) {
    if (settings.singleView) return p.rotationDeg;
    return std::max(p.rotationDeg, p.viewCoverage * 0.5 * nearestOtherCentre(centres, centre));
  };
  spec.pitchDeg = view.pitchDeg + random.symmetric(range(settings.pitchesDeg, view.pitchDeg));
  spec.yawDeg = view.yawDeg + random.symmetric(range(settings.yawsDeg, view.yawDeg));
  spec.rollDeg = random.symmetric(p.rotationDeg);
  spec.scale = 1.0 + random.symmetric(p.scale);
  spec.shiftPixels.x() = random.symmetric(p.shiftPixels);
  spec.shiftPixels.y() = random.symmetric(p.shiftPixels);
  const Lighting base;
  spec.lighting.direction = base.direction.normalized();
  for (int i = 0; i < 3; ++i) spec.lighting.direction[i] += random.symmetric(p.lightDirection);
  if (spec.lighting.direction.z() < 0.3) spec.lighting.direction.z() = 0.3;  // lit from the front
  spec.lighting.ambient = base.ambient + random.symmetric(p.ambient);
  spec.lighting.diffuse = base.diffuse + random.symmetric(p.diffuse);
  if (settings.augmentation.any()) {  // its own stream: the draws above stay as they were
    spec.augmentation =
        drawAugmentation(settings.augmentation, mixKey(key, kAugmentationStream), spec.lighting);
  }
  return spec;
}

SampleFrame frameSample(const LandmarkSet& landmarks, std::pair<int, int> eyes,
                        const SampleSpec& spec, const TrainSettings& settings) {
  if (!landmarks.has(eyes.first) || !landmarks.has(eyes.second)) {
    throw InputError("training: a subject lacks an eye-centre landmark (" +
                     std::to_string(eyes.first + 1) + " or " + std::to_string(eyes.second + 1) +
                     "), which sets the face size");
  }
  const double iodMm = (landmarks.point(eyes.first) - landmarks.point(eyes.second)).norm();
  if (!(iodMm > 1e-6)) throw InputError("training: a subject's eye centres coincide");
  const Eigen::Vector3d centroid = landmarks.centroid();

  const int size = settings.renderSize();
  SampleFrame frame;
  frame.camera = Camera::fromVerticalFov(size, size, 20.0);
  const double focal = frame.camera.focalY();
  const double distance = focal * iodMm / (settings.interOcularPixels() * spec.scale);
  frame.pose = Pose::fromDegrees(spec.pitchDeg, spec.yawDeg, spec.rollDeg);
  frame.pose.translation = -(frame.pose.rotation() * centroid);
  frame.pose.translation.z() -= distance;
  // A shift of s pixels at depth d is s * d / f millimetres; image y points down.
  frame.pose.translation.x() += spec.shiftPixels.x() * distance / focal;
  frame.pose.translation.y() -= spec.shiftPixels.y() * distance / focal;
  const double depthRange = 4.0 * iodMm + 200.0;
  frame.camera = Camera::fromVerticalFov(size, size, 20.0, std::max(10.0, distance - depthRange),
                                         distance + depthRange);
  return frame;
}

TrainingImage renderTrainingImage(OffscreenRenderer& renderer, const LandmarkSet& landmarks,
                                  std::pair<int, int> eyes, const SampleSpec& spec,
                                  const TrainSettings& settings) {
  TrainingImage out;
  out.frame = frameSample(landmarks, eyes, spec, settings);
  out.render = renderer.render(out.frame.pose, out.frame.camera, spec.lighting);
  out.image = out.render.bgra;
  if (spec.augmentation.shadows) {
    const auto [centre, radius] = headSphere(landmarks);
    out.image = renderCastShadows(renderer, out.render, spec.lighting, centre, radius);
  }
  if (spec.augmentation.changesImage()) out.image = augmentImage(out.image, spec.augmentation);
  return out;
}

SamplePatches extractPatches(const cv::Mat& grey, const cv::Mat& alpha,
                             const Eigen::Matrix2Xd& points, const std::vector<bool>& has,
                             const TrainSettings& settings) {
  const std::vector<cv::Mat> greyPyramid = gaussianPyramid(grey, settings.scales);
  std::vector<cv::Mat> alphaPyramid;
  if (!alpha.empty()) alphaPyramid = gaussianPyramid(alpha, settings.scales);
  const auto n = static_cast<int>(points.cols());
  const int size = settings.patchSize;
  const int regionSize = size + 2 * settings.expertRadius;
  SamplePatches patches;
  patches.visible = has;
  for (int s = 0; s < settings.scales; ++s) {
    patches.grey.emplace_back(Eigen::MatrixXf::Zero(size * size, n));
    if (!alpha.empty()) patches.alpha.emplace_back(Eigen::MatrixXf::Zero(size * size, n));
    if (settings.expertRadius > 0) {
      patches.regions.emplace_back(Eigen::MatrixXf::Zero(regionSize * regionSize, n));
    }
  }
  cv::Mat region;
  for (int i = 0; i < n; ++i) {
    if (!has[static_cast<std::size_t>(i)]) continue;
    for (int s = 0; s < settings.scales; ++s) {
      const auto level = static_cast<std::size_t>(s);
      const Eigen::Vector2d at = toPyramidLevel(points.col(i), s);
      auto patch = patches.grey[level].col(i);
      samplePatch(greyPyramid[level], at, size, patch);
      normalisePatch(patch);
      if (!alpha.empty()) samplePatch(alphaPyramid[level], at, size, patches.alpha[level].col(i));
      if (settings.expertRadius > 0) {
        sampleRegion(greyPyramid[level], at, 0.0, regionSize, region);
        auto out = patches.regions[level].col(i);
        for (int r = 0; r < regionSize; ++r) {
          const float* row = region.ptr<float>(r);
          for (int c = 0; c < regionSize; ++c) out[r * regionSize + c] = row[c];
        }
      }
    }
  }
  return patches;
}

SamplePatches renderSample(OffscreenRenderer& renderer, const LandmarkSet& landmarks,
                           std::pair<int, int> eyes, const SampleSpec& spec,
                           const TrainSettings& settings) {
  const TrainingImage training = renderTrainingImage(renderer, landmarks, eyes, spec, settings);
  const SampleFrame& frame = training.frame;
  const RenderResult& result = training.render;

  cv::Mat alpha8;
  cv::extractChannel(result.bgra, alpha8, 3);
  cv::Mat alpha;
  alpha8.convertTo(alpha, CV_32F, 1.0 / 255.0);
  const int n = landmarks.size();
  Eigen::Matrix2Xd points = Eigen::Matrix2Xd::Zero(2, n);
  std::vector<bool> has(static_cast<std::size_t>(n), false);
  for (int i = 0; i < n; ++i) {
    if (!landmarks.has(i)) continue;
    has[static_cast<std::size_t>(i)] = true;
    points.col(i) = projectPoint(landmarks.point(i), frame.pose, frame.camera);
  }
  SamplePatches patches = extractPatches(toGreyFloat(training.image), alpha, points, has, settings);
  for (int i = 0; i < n; ++i) {
    if (has[static_cast<std::size_t>(i)]) {
      patches.visible[static_cast<std::size_t>(i)] = result.isVisible(landmarks.point(i));
    }
  }
  return patches;
}

}  // namespace clm3d
