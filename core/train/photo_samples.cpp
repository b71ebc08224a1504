#include "core/train/photo_samples.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "core/common/error.hpp"
#include "core/common/job_progress.hpp"
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

// The fit that places a photo: stateFromPoints's, with fewer Levenberg-Marquardt iterations per
// starting yaw (the view, scale and in-plane rotation it gives do not need the last 0.01 pixel).
const PointsFitSettings kPlacementFit{0.25, 20};

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

// A perturbation of a photo's placement, like a render's: relative scale, in-plane rotation
// (degrees) and shift (pixels at the finest scale).
struct Jitter {
  double scale = 1.0, rollDeg = 0.0;
  Eigen::Vector2d shift{0.0, 0.0};
};

// Where a copy goes and how it is brought there: its view, the scale that gives the face the
// training eye distance, its in-plane rotation and the centre of its fitted points.
struct Frame {
  int view = -1;  // -1: the fit failed (`why`)
  double pitchDeg = 0, yawDeg = 0, rollDeg = 0;
  double scale = 0, angle = 0;
  Eigen::Vector2d centre{0.0, 0.0};
  std::string why;
};

// The copy's trusted points (the others zeroed) as they are or mirrored in an image `width` wide.
Eigen::Matrix2Xd copyPoints(const TrainingPhoto& photo, const Scheme& scheme, int width,
                            bool mirror, std::vector<bool>& trusted) {
  const int n = photo.points.size();
  Eigen::Matrix2Xd points = Eigen::Matrix2Xd::Zero(2, n);
  trusted.assign(static_cast<std::size_t>(n), false);
  for (int i = 0; i < n; ++i) {
    const int source = mirror ? scheme.mirrorOf(i) : i;
    if (!photo.trusted[static_cast<std::size_t>(source)]) continue;
    const Eigen::Vector3d p = photo.points.point(source);
    points.col(i) = Eigen::Vector2d(mirror ? width - 1.0 - p.x() : p.x(), p.y());
    trusted[static_cast<std::size_t>(i)] = true;
  }
  return points;
}

// The pose and shape fitted to the photo's trusted points (stateFromPoints), and from them the
// photo's frame.
Frame frameFromPoints(const Eigen::Matrix2Xd& points, const std::vector<bool>& trusted,
                      cv::Size size, const ClmModel& model, std::pair<int, int> eyes,
                      const TrainSettings& settings, const std::vector<ViewCentre>& views) {
  const Camera camera = Camera::fromVerticalFov(size.width, size.height, kPhotoFovDeg);
  Frame frame;
  FitState state;
  try {
    state = stateFromPoints(model, camera, points, trusted, kPlacementFit);
  } catch (const InputError& e) {
    frame.why = e.what();
    return frame;
  }
  frame.pitchDeg = degrees(state.pose.pitch);
  frame.yawDeg = degrees(state.pose.yaw);
  frame.rollDeg = degrees(state.pose.roll);
  // Scale: the fitted 3D eye distance at the face's depth, as frameSample sizes the renders.
  const auto [left, right] = eyes;
  const Eigen::Matrix3Xd shape3d = model.shape.shape(state.shape);
  const double eyeMm = (shape3d.col(left) - shape3d.col(right)).norm();
  const double pixelsPerMm =
      camera.focalY() * state.pose.scale / std::max(-state.pose.translation.z(), 1e-6);
  frame.scale = settings.interOcularPixels() / std::max(eyeMm * pixelsPerMm, 1e-6);
  if (!std::isfinite(frame.scale) || frame.scale <= 0.0) {
    frame.why = "the fitted face has no size";
    return frame;
  }
  const Eigen::Matrix2Xd turned = projectState(model, camera, state);
  FitState upright = state;
  upright.pose.roll = 0.0;
  frame.angle = inPlaneRotation(projectState(model, camera, upright), turned);
  frame.centre = turned.rowwise().mean();
  frame.view = nearestView(views, frame.pitchDeg, frame.yawDeg);
  return frame;
}

// The frame of the photo's left-right mirror image (an image `width` wide): the mirrored pose
// (yaw and roll negated), the same scale, the in-plane rotation negated and the centre mirrored.
// The shape model fitted to the mirrored points would be the mirror of this fit up to the model's
// own asymmetry, which moves the frame by far less than the perturbations the renders are given.
Frame mirroredFrame(const Frame& frame, int width, const std::vector<ViewCentre>& views) {
  Frame mirror = frame;
  if (frame.view < 0) return mirror;
  mirror.yawDeg = -frame.yawDeg;
  mirror.rollDeg = -frame.rollDeg;
  mirror.angle = -frame.angle;
  mirror.centre.x() = width - 1.0 - frame.centre.x();
  mirror.view = nearestView(views, mirror.pitchDeg, mirror.yawDeg);
  return mirror;
}

void placeCopy(const Copy& copy, const Frame& frame, const TrainSettings& settings,
               const std::vector<Jitter>& jitters, std::vector<PhotoSample>& samples) {
  const int view = frame.view;
  const double scale = frame.scale;
  const double angle = frame.angle;
  const Eigen::Vector2d centre = frame.centre;

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
  const auto count = static_cast<int>(photos.size());
  std::vector<PhotoPlacement> placed(photos.size());
  std::vector<cv::Mat> images(photos.size());
  std::array<std::vector<Frame>, 2> frames;  // per copy (as it is, mirrored), per photo
  frames[0].resize(photos.size());
  frames[1].resize(photos.size());
  // Each photo is finished twice: placed (1), then sampled (3).
  JobProgress done(progress, 2 * count, "photos");

  // 1. Each photo's pose from its own points, and so its view and its mirror image's.
  parallelFor(count, settings.threads, [&](int index) {
    const auto k = static_cast<std::size_t>(index);
    if (cancel) cancel->throwIfCancelled();
    const TrainingPhoto& photo = photos[k];
    PhotoPlacement& placement = placed[k];
    placement.id = photo.id;
    images[k] =
        photo.pixels.empty() ? cv::imread(photo.image.string(), cv::IMREAD_COLOR) : photo.pixels;
    const int trusted =
        static_cast<int>(std::count(photo.trusted.begin(), photo.trusted.end(), true));
    if (images[k].empty()) {
      placement.skipped = "cannot read the image";
    } else if (trusted < kMinTrustedPoints) {
      placement.skipped = "only " + std::to_string(trusted) + " trusted points";
    } else {
      std::vector<bool> copyTrusted;
      const Eigen::Matrix2Xd points = copyPoints(photo, scheme, images[k].cols, false, copyTrusted);
      frames[0][k] =
          frameFromPoints(points, copyTrusted, images[k].size(), model, eyes, settings, views);
      frames[1][k] = mirroredFrame(frames[0][k], images[k].cols, views);
      placement.pitchDeg = frames[0][k].pitchDeg;
      placement.yawDeg = frames[0][k].yawDeg;
      placement.rollDeg = frames[0][k].rollDeg;
      if (frames[0][k].view < 0) placement.skipped = frames[0][k].why;
    }
    done.finished();
  });

  // 2. Which copies join their views: not those whose view is a mirrored one (the mirror image
  // trains its source), and no more than the source's per_view of each source in each view, the
  // first in input order.
  std::array<std::vector<char>, 2> keep{std::vector<char>(photos.size(), 0),
                                        std::vector<char>(photos.size(), 0)};
  std::map<std::pair<int, int>, int> inView;  // (source, view) -> copies kept
  for (std::size_t k = 0; k < photos.size(); ++k) {
    if (!placed[k].skipped.empty()) continue;
    for (std::size_t copyIndex = 0; copyIndex < 2; ++copyIndex) {
      const int view = frames[copyIndex][k].view;
      if (mirror && views[static_cast<std::size_t>(view)].yawDeg > 0) continue;
      int& kept = inView[{photos[k].source, view}];
      if (photos[k].perView > 0 && kept >= photos[k].perView) {
        ++placed[k].capped;
        continue;
      }
      ++kept;
      keep[copyIndex][k] = 1;
      ++placed[k].samples;
    }
    if (placed[k].samples == 0) images[k].release();
  }

  // 3. The kept copies brought to the training frame and sampled.
  std::vector<std::vector<PhotoSample>> results(photos.size());
  parallelFor(count, settings.threads, [&](int index) {
    const auto k = static_cast<std::size_t>(index);
    if (cancel) cancel->throwIfCancelled();
    for (int copyIndex = 0; copyIndex < 2 && placed[k].samples > 0; ++copyIndex) {
      if (!keep[static_cast<std::size_t>(copyIndex)][k]) continue;
      const TrainingPhoto& photo = photos[k];
      Copy copy;
      if (copyIndex == 0) {
        copy.image = images[k];
      } else {
        cv::flip(images[k], copy.image, 1);
      }
      copy.points = copyPoints(photo, scheme, images[k].cols, copyIndex == 1, copy.trusted);
      // The placement itself, then settings.photoJitter perturbed ones.
      std::vector<Jitter> jitters(1);
      SplitMixRandom random(mixKey(mixKey(settings.seed, k), copyIndex));
      const PerturbationSettings& p = settings.perturbation;
      for (int j = 0; j < settings.photoJitter; ++j) {
        jitters.push_back(
            {1.0 + random.symmetric(p.scale), random.symmetric(p.rotationDeg),
             Eigen::Vector2d(random.symmetric(p.shiftPixels), random.symmetric(p.shiftPixels))});
      }
      std::vector<PhotoSample> copySamples;
      placeCopy(copy, frames[static_cast<std::size_t>(copyIndex)][k], settings, jitters,
                copySamples);
      for (PhotoSample& sample : copySamples) {
        sample.id = photo.id + (copyIndex == 0 ? "" : " (mirrored)");
        results[k].push_back(std::move(sample));
      }
    }
    images[k].release();
    done.finished();
  });

  std::vector<PhotoSample> samples;
  for (auto& list : results) {
    for (PhotoSample& sample : list) samples.push_back(std::move(sample));
  }
  if (placements) *placements = std::move(placed);
  return samples;
}

}  // namespace clm3d
