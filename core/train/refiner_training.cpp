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

// The stages' feature windows, in eye distances: the last stage's, and the factor between one
// stage's and the next's: wide first (a start that is far off), narrower as the points close in.
// Five stages from 1.0 to 0.35 were better than four from 0.8 (0.0504 against 0.0526 from the
// detector on 100 held-out LFPW training photos; from the 5-point start 0.0417 against 0.0425).
constexpr double kLastWindow = 0.35;
constexpr double kWindowGrowth = 1.3;
// The regressions' ridge: 0.2 against 0.05 took the same held-out photos from 0.0425 to 0.0415
// (5-point start), 0.0526 to 0.0528 (detector).
constexpr double kRidge = 0.2;
// Each training start's shape taken up to half-way towards another photo's (DescentTrainSettings::
// otherShape): a search leaves the shape model's idea of the face, not a moved copy of the true
// one. On 100 held-out LFPW training photos from the detector (rlms): mean 0.0634 -> 0.0603,
// median 0.0453 -> 0.0410 (1.0: 0.0608, 0.0402); from the 5-point start 0.0479 -> 0.0473 (1.0:
// 0.0480).
constexpr double kOtherShape = 0.5;
// The fewest faces (photos and their mirror images) the refiner's check is learnt from.
constexpr std::size_t kCheckMinFaces = 40;

}  // namespace

DescentRefiner trainPhotoRefiner(const std::vector<TrainingPhoto>& photos, const Scheme& scheme,
                                 const TrainSettings& settings, const ProgressCallback& progress,
                                 const CancelToken* cancel) {
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
        if (image.empty() || (truth.col(leftEye) - truth.col(rightEye)).norm() < 1.0) return;
        cv::Mat flipped;
        cv::flip(image, flipped, 1);
        Eigen::Matrix2Xd mirrored(2, n);
        for (int i = 0; i < n; ++i)
          mirrored.col(mirror[i]) = Eigen::Vector2d(image.cols - 1 - truth(0, i), truth(1, i));
        for (int side = 0; side < 2; ++side) {
          const Eigen::Matrix2Xd& points = side == 0 ? truth : mirrored;
          DescentPhoto& slot = slots[2 * static_cast<std::size_t>(index) + side];
          slot.region = descentRegion(side == 0 ? image : flipped, points, leftEye, rightEye);
          slot.truth = slot.region.toRegion(points);
        }
      },
      cancel);
  std::vector<DescentPhoto> faces;
  for (DescentPhoto& slot : slots) {
    if (!slot.region.grey.empty()) faces.push_back(std::move(slot));
  }
  if (faces.empty()) return {};
  if (progress) progress(0.3, "refiner");

  DescentTrainSettings train;
  train.windows.clear();
  for (int stage = 0; stage < settings.refinerStages; ++stage) {
    train.windows.push_back(kLastWindow *
                            std::pow(kWindowGrowth, settings.refinerStages - 1 - stage));
  }
  train.ridge = kRidge;
  train.otherShape = kOtherShape;
  train.shapeTerms = true;
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
