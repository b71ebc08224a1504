#include "core/train/photo_samples.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "core/common/error.hpp"
#include "core/common/parallel_for.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/detect/initialisation.hpp"
#include "core/fit/response_map.hpp"
#include "core/geometry/camera.hpp"
#include "core/image/pyramid.hpp"
#include "core/train/training_sample.hpp"

namespace clm3d {
namespace {

// The camera the photos are fitted with: the fitter's default field of view.
constexpr double kPhotoFovDeg = 40.0;
constexpr int kMinTrustedPoints = 6;

int nearestView(const std::vector<ViewCentre>& views, double pitchDeg, double yawDeg) {
  int best = 0;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < views.size(); ++v) {
    const double d = std::hypot(views[v].pitchDeg - pitchDeg, views[v].yawDeg - yawDeg);
    if (d < bestDistance) {
      bestDistance = d;
      best = static_cast<int>(v);
    }
  }
  return best;
}

struct Copy {
  cv::Mat image;  // BGR or grey 8-bit
  Eigen::Matrix2Xd points;
  std::vector<bool> trusted;
};

Copy mirrored(const Copy& original, const Scheme& scheme) {
  Copy copy;
  cv::flip(original.image, copy.image, 1);
  const auto n = static_cast<int>(original.points.cols());
  copy.points.resize(2, n);
  copy.trusted.assign(static_cast<std::size_t>(n), false);
  const double width = original.image.cols;
  for (int i = 0; i < n; ++i) {
    const int source = scheme.mirrorOf(i);
    copy.points(0, i) = width - 1.0 - original.points(0, source);
    copy.points(1, i) = original.points(1, source);
    copy.trusted[static_cast<std::size_t>(i)] = original.trusted[static_cast<std::size_t>(source)];
  }
  return copy;
}

// A perturbation of a photo's placement, like a render's: relative scale, in-plane rotation
// (degrees) and shift (pixels at the finest scale).
struct Jitter {
  double scale = 1.0, rollDeg = 0.0;
  Eigen::Vector2d shift{0.0, 0.0};
};

bool placeCopy(const Copy& copy, const ClmModel& model, std::pair<int, int> eyes,
               const TrainSettings& settings, const std::vector<ViewCentre>& views,
               const std::vector<Jitter>& jitters, std::vector<PhotoSample>& samples,
               PhotoPlacement& placed, std::string& why) {
  const Camera camera = Camera::fromVerticalFov(copy.image.cols, copy.image.rows, kPhotoFovDeg);
  FitState state;
  try {
    state = stateFromPoints(model, camera, copy.points, copy.trusted);
  } catch (const InputError& e) {
    why = e.what();
    return false;
  }
  placed.pitchDeg = degrees(state.pose.pitch);
  placed.yawDeg = degrees(state.pose.yaw);
  placed.rollDeg = degrees(state.pose.roll);
  const int view = nearestView(views, placed.pitchDeg, placed.yawDeg);

  // Scale: the fitted 3D eye distance at the face's depth, as frameSample sizes the renders.
  const auto [left, right] = eyes;
  const Eigen::Matrix3Xd shape3d = model.shape.shape(state.shape);
  const double eyeMm = (shape3d.col(left) - shape3d.col(right)).norm();
  const double pixelsPerMm =
      camera.focalY() * state.pose.scale / std::max(-state.pose.translation.z(), 1e-6);
  const double scale = settings.interOcularPixels() / std::max(eyeMm * pixelsPerMm, 1e-6);
  if (!std::isfinite(scale) || scale <= 0.0) {
    why = "the fitted face has no size";
    return false;
  }
  const Eigen::Matrix2Xd turned = projectState(model, camera, state);
  FitState upright = state;
  upright.pose.roll = 0.0;
  const double angle = inPlaneRotation(projectState(model, camera, upright), turned);
  const Eigen::Vector2d centre = turned.rowwise().mean();

  // Shrinking by area first so that a large photo does not alias, then turning with bilinear.
  cv::Mat source = copy.image;
  Eigen::Matrix2Xd points = copy.points;
  Eigen::Vector2d from = centre;
  double remaining = scale;
  if (scale < 0.8) {
    cv::resize(copy.image, source, cv::Size(), scale, scale, cv::INTER_AREA);
    const auto shrink = [&](const Eigen::Vector2d& p) {
      return Eigen::Vector2d((p.x() + 0.5) * source.cols / copy.image.cols - 0.5,
                             (p.y() + 0.5) * source.rows / copy.image.rows - 0.5);
    };
    for (Eigen::Index i = 0; i < points.cols(); ++i) points.col(i) = shrink(points.col(i));
    from = shrink(centre);
    remaining = scale * copy.image.cols / source.cols;
  }
  const int size = settings.renderSize();
  const Eigen::Vector2d middle((size - 1) / 2.0, (size - 1) / 2.0);
  for (const Jitter& jitter : jitters) {
    // Canvas pixel q = s Rot(-angle + jitter) (x - from) + canvas centre + shift, with Rot as
    // sampleRegion's.
    const double turn = -angle + radians(jitter.rollDeg);
    const double c = std::cos(turn) * remaining * jitter.scale;
    const double s = std::sin(turn) * remaining * jitter.scale;
    const Eigen::Vector2d target = middle + jitter.shift;
    Eigen::Matrix<double, 2, 3> map;
    map << c, s, target.x() - c * from.x() - s * from.y(),  //
        -s, c, target.y() + s * from.x() - c * from.y();
    cv::Mat warped;
    const cv::Matx23d cvMap(map(0, 0), map(0, 1), map(0, 2), map(1, 0), map(1, 1), map(1, 2));
    cv::warpAffine(source, warped, cvMap, cv::Size(size, size), cv::INTER_LINEAR,
                   cv::BORDER_REPLICATE);
    Eigen::Matrix2Xd canvasPoints(2, points.cols());
    for (Eigen::Index i = 0; i < points.cols(); ++i) {
      canvasPoints.col(i) = map.leftCols<2>() * points.col(i) + map.col(2);
    }
    PhotoSample sample;
    sample.view = view;
    sample.patches =
        extractPatches(toGreyFloat(warped), cv::Mat(), canvasPoints, copy.trusted, settings);
    samples.push_back(std::move(sample));
  }
  return true;
}

}  // namespace

std::vector<PhotoSample> preparePhotoSamples(const std::vector<TrainingPhoto>& photos,
                                             const std::string& schemeJson, const ShapeModel& shape,
                                             const TrainSettings& settings,
                                             std::vector<PhotoPlacement>* placements,
                                             const ProgressCallback& progress,
                                             const CancelToken* cancel) {
  ClmModel model;  // the shape and scheme are all stateFromPoints needs
  model.schemeJson = schemeJson;
  model.shape = shape;
  model.singleView = settings.singleView;
  const Scheme scheme = model.scheme();
  const std::pair<int, int> eyes = scheme.normalisationPair();
  const std::vector<ViewCentre> views = settings.views();
  const bool mirror = settings.mirrorRightViews && !settings.singleView;
  std::vector<std::vector<PhotoSample>> results(photos.size());
  std::vector<PhotoPlacement> placed(photos.size());
  std::atomic<int> done{0};
  parallelFor(static_cast<int>(photos.size()), settings.threads, [&](int index) {
    const auto k = static_cast<std::size_t>(index);
    if (cancel) cancel->throwIfCancelled();
    const TrainingPhoto& photo = photos[k];
    PhotoPlacement& placement = placed[k];
    placement.id = photo.id;
    Copy original;
    original.image = cv::imread(photo.image.string(), cv::IMREAD_COLOR);
    const int trusted =
        static_cast<int>(std::count(photo.trusted.begin(), photo.trusted.end(), true));
    if (original.image.empty()) {
      placement.skipped = "cannot read the image";
    } else if (trusted < kMinTrustedPoints) {
      placement.skipped = "only " + std::to_string(trusted) + " trusted points";
    } else {
      original.points = photo.points.matrix().topRows(2);
      original.trusted = photo.trusted;
      for (int i = 0; i < photo.points.size(); ++i) {
        if (!photo.trusted[static_cast<std::size_t>(i)]) original.points.col(i).setZero();
      }
      const Copy flipped = mirrored(original, scheme);
      for (int copyIndex = 0; copyIndex < 2; ++copyIndex) {
        const Copy& copy = copyIndex == 0 ? original : flipped;
        // The placement itself, then settings.photoJitter perturbed ones.
        std::vector<Jitter> jitters(1);
        SplitMixRandom random(mixKey(mixKey(settings.seed, k), copyIndex));
        const PerturbationSettings& p = settings.perturbation;
        for (int j = 0; j < settings.photoJitter; ++j) {
          jitters.push_back(
              {1.0 + random.symmetric(p.scale), random.symmetric(p.rotationDeg),
               Eigen::Vector2d(random.symmetric(p.shiftPixels), random.symmetric(p.shiftPixels))});
        }
        std::vector<PhotoSample> placedSamples;
        PhotoPlacement pose;
        std::string why;
        if (!placeCopy(copy, model, eyes, settings, views, jitters, placedSamples, pose, why)) {
          placement.skipped = why;
          break;
        }
        if (copyIndex == 0) {
          placement.pitchDeg = pose.pitchDeg;
          placement.yawDeg = pose.yawDeg;
          placement.rollDeg = pose.rollDeg;
        }
        const int view = placedSamples.front().view;
        if (mirror && views[static_cast<std::size_t>(view)].yawDeg > 0) continue;
        for (PhotoSample& sample : placedSamples) {
          sample.id = photo.id + (copyIndex == 0 ? "" : " (mirrored)");
          results[k].push_back(std::move(sample));
        }
        ++placement.samples;
      }
    }
    const int finished = ++done;
    if (progress) progress(static_cast<double>(finished) / photos.size(), "photos");
  });

  std::vector<PhotoSample> samples;
  for (auto& list : results) {
    for (PhotoSample& sample : list) samples.push_back(std::move(sample));
  }
  if (placements) *placements = std::move(placed);
  return samples;
}

}  // namespace clm3d
