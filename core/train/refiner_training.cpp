#include "core/train/refiner_training.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/common/error.hpp"
#include "core/common/parallel_for.hpp"
#include "core/refine/descent_check.hpp"
#include "core/refine/descent_refinement.hpp"

namespace clm3d {

namespace {

// A point is refined when at least this share of the photos trusts it (and its mirror image).
constexpr double kMarkedShare = 0.9;

// The fewest faces (photos and their mirror images) the refiner's check is learnt from.
constexpr std::size_t kCheckMinFaces = 40;

}  // namespace

DescentRefiner trainPhotoRefiner(const std::vector<TrainingPhoto>& allPhotos, const Scheme& scheme,
                                 const TrainSettings& settings, const ProgressCallback& progress,
                                 const CancelToken* cancel) {
  std::vector<TrainingPhoto> photos;  // those of the sources the refiner learns from
  for (const TrainingPhoto& photo : allPhotos) {
    if (photo.refiner) photos.push_back(photo);
  }
  if (settings.refinerStages <= 0 || photos.empty()) return {};
  const int count = scheme.size();
  std::vector<int> marked(static_cast<std::size_t>(count), 0);
  for (const TrainingPhoto& photo : photos) {
    for (int i = 0; i < count; ++i) marked[static_cast<std::size_t>(i)] += photo.trusted[i];
  }
  const auto often = [&](int i) {
    return marked[static_cast<std::size_t>(i)] >= kMarkedShare * static_cast<double>(photos.size());
  };
  std::vector<int> landmarks;
  for (int i = 0; i < count; ++i) {
    if (often(i) && often(scheme.mirrorOf(i))) landmarks.push_back(i);
  }
  const auto [leftIndex, rightIndex] = scheme.normalisationPair();
  const auto positionOf = [&](int landmark) {
    return static_cast<int>(std::find(landmarks.begin(), landmarks.end(), landmark) -
                            landmarks.begin());
  };
  const int leftEye = positionOf(leftIndex), rightEye = positionOf(rightIndex);
  const int n = static_cast<int>(landmarks.size());
  if (n < 3 || leftEye == n || rightEye == n) return {};
  std::vector<int> mirror(landmarks.size());
  for (int i = 0; i < n; ++i) mirror[i] = positionOf(scheme.mirrorOf(landmarks[i]));

  if (progress) progress(0.0, "refiner");
  // Two regions per photo (as it is, mirrored); a slot stays empty when the photo is unusable.
  std::vector<DescentPhoto> slots(2 * photos.size());
  parallelFor(
      static_cast<int>(photos.size()), settings.threads,
      [&](int index) {
        const TrainingPhoto& photo = photos[static_cast<std::size_t>(index)];
        Eigen::Matrix2Xd truth(2, n);
        for (int i = 0; i < n; ++i) {
          if (!photo.trusted[static_cast<std::size_t>(landmarks[i])]) return;
          truth.col(i) = photo.points.point(landmarks[i]).head<2>();
        }
        const cv::Mat image = cv::imread(photo.image.string(), cv::IMREAD_GRAYSCALE);
        std::vector<DescentPhoto> both =
            descentPhotoAndMirror(image, truth, mirror, leftEye, rightEye);
        for (std::size_t side = 0; side < both.size(); ++side) {
          slots[2 * static_cast<std::size_t>(index) + side] = std::move(both[side]);
        }
      },
      cancel);
  std::vector<DescentPhoto> faces;
  for (DescentPhoto& slot : slots) {
    if (!slot.region.grey.empty()) faces.push_back(std::move(slot));
  }
  if (faces.empty()) return {};
  if (progress) progress(0.3, "refiner");

  DescentTrainSettings train;  // its defaults are the refiner's (ridge, other shapes, shape terms)
  train.windows = descentWindows(settings.refinerStages);
  train.startsPerPhoto = settings.refinerStarts;
  train.seed = settings.seed;
  train.threads = settings.threads;
  DescentRefiner refiner = trainDescentRefiner(faces, landmarks, leftEye, rightEye, train, cancel);
  if (progress) progress(0.8, "refiner check");

  DescentCheckSettings checkSettings;
  checkSettings.seed = settings.seed;
  checkSettings.threads = settings.threads;
  // Too few photos to learn a check and calibrate it on others: the refiner goes without one, and
  // fits keep the search's confidence.
  if (faces.size() >= kCheckMinFaces) {
    try {
      refiner.check = trainDescentCheck(faces, refiner, checkSettings, cancel);
    } catch (const InputError&) {
      // Every refined start right (or every one wrong): nothing to tell apart; no check.
    }
  }
  if (progress) progress(1.0, "refiner");
  return refiner;
}

}  // namespace clm3d
