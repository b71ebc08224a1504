#include "core/refine/descent_refinement.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>

#include "core/common/error.hpp"
#include "core/common/parallel_for.hpp"
#include "core/refine/descent_check.hpp"
#include "core/refine/detail/descent_features.hpp"
#include "core/refine/detail/ridge_regression.hpp"

namespace clm3d {

namespace {

// Margin of the region around the points, in eye distances (the widest window reaches 0.4).
constexpr double kRegionMargin = 1.2;

// The points' departure from the mean shape (normalised coordinates) enters a stage's regression
// as 2 N more features, scaled by this: the image features are unit-length blocks of 128 values
// (about 0.05 each), the departures a few hundredths of the eye distance. A stage then corrects a
// shape the search left off the faces' typical ones (a chin too short for the brows, say) from the
// shape as well as the image. On 100 held-out LFPW training photos (rlms, refiner learnt on the
// other 705), from the truth's 5 points: 0.0473 -> 0.0456 (median 0.0446 -> 0.0418; scale 1
// 0.0459, 0.5 0.0464); from the detector 0.0603 -> 0.0589 (median 0.0410 -> 0.0394). With seed 2:
// 0.0476 -> 0.0456 and 0.0611 -> 0.0589.
constexpr double kShapeFeatureScale = 3.0;

// The points' departure from the mean shape, 2 N values (x then y per point).
Eigen::VectorXf departure(const Eigen::Matrix2Xd& normalised, const Eigen::Matrix2Xd& meanShape) {
  const Eigen::Matrix2Xd difference = normalised - meanShape;
  return Eigen::Map<const Eigen::VectorXd>(difference.data(), difference.size()).cast<float>();
}

// The points moved by a stage's step (2 N values, x then y per point) in `frame`'s normalised
// coordinates.
Eigen::Matrix2Xd stepped(const Similarity2& frame, const Eigen::Matrix2Xd& points,
                         const Eigen::VectorXf& step) {
  const Eigen::Matrix2Xd moved =
      frame.inverse(points) +
      Eigen::Map<const Eigen::Matrix2Xf>(step.data(), 2, points.cols()).cast<double>();
  return frame.apply(moved);
}

Eigen::Matrix2Xd applyStage(const DescentStage& stage, const Eigen::Matrix2Xd& meanShape,
                            const cv::Mat& grey, const Eigen::Matrix2Xd& points) {
  const Similarity2 frame = alignSimilarity2(meanShape, points);
  const Eigen::Matrix2Xd normalised = frame.inverse(points);
  const Eigen::VectorXf features = descentFeatures(grey, frame, normalised, stage.window);
  Eigen::VectorXf step = stage.weights * (features - stage.featureMean) + stage.bias;
  if (stage.shapeWeights.size() > 0) step += stage.shapeWeights * departure(normalised, meanShape);
  return stepped(frame, points, step);
}

Eigen::Matrix2Xd withEyesAtOrigin(const Eigen::Matrix2Xd& shape, int leftEye, int rightEye) {
  const Eigen::Vector2d eyes = 0.5 * (shape.col(leftEye) + shape.col(rightEye));
  const double distance = (shape.col(leftEye) - shape.col(rightEye)).norm();
  return (shape.colwise() - eyes) / distance;
}

// The Procrustes mean of the true points.
Eigen::Matrix2Xd meanShapeOf(const std::vector<DescentPhoto>& photos, int leftEye, int rightEye) {
  Eigen::Matrix2Xd mean = withEyesAtOrigin(photos.front().truth, leftEye, rightEye);
  for (int round = 0; round < 4; ++round) {
    Eigen::Matrix2Xd sum = Eigen::Matrix2Xd::Zero(2, mean.cols());
    for (const DescentPhoto& photo : photos)
      sum += alignSimilarity2(mean, photo.truth).inverse(photo.truth);
    mean = withEyesAtOrigin(sum / static_cast<double>(photos.size()), leftEye, rightEye);
  }
  return mean;
}

// The starts a cascade learns from: `perPhoto` per photo, each the truth (its shape taken up to
// `otherShape` of the way towards another photo's) moved by `start`; drawn per photo from its own
// seed, so they do not depend on the thread count.
std::vector<Eigen::Matrix2Xd> drawStarts(const std::vector<DescentPhoto>& photos, int leftEye,
                                         int rightEye, int perPhoto, double otherShape,
                                         const StartPerturbation& start, std::uint64_t seed) {
  std::vector<Eigen::Matrix2Xd> starts(photos.size() * static_cast<std::size_t>(perPhoto));
  for (std::size_t p = 0; p < photos.size(); ++p) {
    std::mt19937_64 random(seed * 1000003u + p);
    const Eigen::Matrix2Xd& truth = photos[p].truth;
    const double eyeDistance = (truth.col(leftEye) - truth.col(rightEye)).norm();
    for (int k = 0; k < perPhoto; ++k) {
      Eigen::Matrix2Xd shape = truth;
      if (otherShape > 0.0 && photos.size() > 1) {
        std::uniform_int_distribution<std::size_t> pick(0, photos.size() - 2);
        std::size_t q = pick(random);
        q += q >= p ? 1 : 0;
        const Eigen::Matrix2Xd& other = photos[q].truth;
        const double share = std::uniform_real_distribution<double>(0.0, otherShape)(random);
        shape += share * (alignSimilarity2(other, truth).apply(other) - truth);
      }
      starts[p * static_cast<std::size_t>(perPhoto) + static_cast<std::size_t>(k)] =
          perturbedPoints(shape, eyeDistance, start, random);
    }
  }
  return starts;
}

// One stage's regression data over every start: the image features at `window` (and, with shape
// terms, the scaled departures from the mean shape) and the steps to the truth, one column per
// start, in the frame that maps the mean shape onto the start (into `frames`).
struct StageSamples {
  Eigen::MatrixXf features;
  Eigen::MatrixXf targets;
};
StageSamples stageSamples(const std::vector<DescentPhoto>& photos, int perPhoto,
                          const std::vector<Eigen::Matrix2Xd>& starts,
                          const Eigen::Matrix2Xd& meanShape, double window, bool shapeTerms,
                          std::vector<Similarity2>& frames, int threads,
                          const CancelToken* cancel) {
  const auto n = meanShape.cols();
  const Eigen::Index d = n * kDescentFeaturesPerPoint;
  const Eigen::Index shapeRows = shapeTerms ? 2 * n : 0;
  const int m = static_cast<int>(starts.size());
  StageSamples samples{Eigen::MatrixXf(d + shapeRows, m), Eigen::MatrixXf(2 * n, m)};
  frames.resize(starts.size());
  parallelFor(
      m, threads,
      [&](int s) {
        const DescentPhoto& photo = photos[static_cast<std::size_t>(s / perPhoto)];
        const Similarity2& frame = frames[s] = alignSimilarity2(meanShape, starts[s]);
        const Eigen::Matrix2Xd start = frame.inverse(starts[s]);
        samples.features.col(s).head(d) = descentFeatures(photo.region.grey, frame, start, window);
        if (shapeRows > 0) {
          samples.features.col(s).tail(shapeRows) =
              static_cast<float>(kShapeFeatureScale) * departure(start, meanShape);
        }
        const Eigen::Matrix2Xd step = frame.inverse(photo.truth) - start;
        samples.targets.col(s) =
            Eigen::Map<const Eigen::VectorXd>(step.data(), 2 * n).cast<float>();
      },
      cancel);
  return samples;
}

}  // namespace

Eigen::Matrix2Xd DescentRegion::toRegion(const Eigen::Matrix2Xd& image) const {
  return scale * (image.colwise() - offset);
}

Eigen::Matrix2Xd DescentRegion::toImage(const Eigen::Matrix2Xd& region) const {
  return (region / scale).colwise() + offset;
}

DescentRegion greyRegion(const cv::Mat& image, const Eigen::Matrix2Xd& points, double margin,
                         double scale) {
  if (image.empty()) throw InputError("refine: the image is empty");
  const int type = image.type();
  if (type != CV_8UC1 && type != CV_8UC3 && type != CV_8UC4 && type != CV_32FC1)
    throw InputError("refine: unsupported image type (need 8-bit grey, BGR or BGRA, or float)");
  const Eigen::Vector2d low = points.rowwise().minCoeff().array() - margin;
  const Eigen::Vector2d high = points.rowwise().maxCoeff().array() + margin;
  const auto clampTo = [](double v, int lo, int hi) {
    return static_cast<int>(std::clamp(v, static_cast<double>(lo), static_cast<double>(hi)));
  };
  const int x0 = clampTo(std::floor(low.x()), 0, image.cols - 1);
  const int y0 = clampTo(std::floor(low.y()), 0, image.rows - 1);
  const int x1 = clampTo(std::ceil(high.x()) + 1, x0 + 1, image.cols);
  const int y1 = clampTo(std::ceil(high.y()) + 1, y0 + 1, image.rows);
  // The face's part only is turned grey (a whole photo's conversion cost more than the refiner).
  const cv::Mat part = image(cv::Rect(x0, y0, x1 - x0, y1 - y0));
  cv::Mat roi = part;
  if (type == CV_8UC3) {
    cv::cvtColor(part, roi, cv::COLOR_BGR2GRAY);
  } else if (type == CV_8UC4) {
    cv::cvtColor(part, roi, cv::COLOR_BGRA2GRAY);
  }
  const int width = std::max(1, static_cast<int>(std::lround(roi.cols * scale)));
  const int height = std::max(1, static_cast<int>(std::lround(roi.rows * scale)));
  cv::Mat resized;
  cv::resize(roi, resized, cv::Size(width, height), 0, 0,
             scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
  DescentRegion region;
  // 8-bit images are brought to [0, 1], as float images come (the features ignore the range).
  resized.convertTo(region.grey, CV_32F, image.depth() == CV_8U ? 1.0 / 255.0 : 1.0);
  region.scale = static_cast<double>(width) / roi.cols;
  region.offset = Eigen::Vector2d(x0, y0);
  return region;
}

DescentRegion descentRegion(const cv::Mat& image, const Eigen::Matrix2Xd& points, int leftEye,
                            int rightEye) {
  if (image.empty()) throw InputError("refine: the image is empty");
  const double eyeDistance = (points.col(leftEye) - points.col(rightEye)).norm();
  if (!(eyeDistance > 0.0) || !points.allFinite())
    throw InputError("refine: the points' eyes coincide or are not finite");
  return greyRegion(image, points, kRegionMargin * eyeDistance, kDescentEyeDistance / eyeDistance);
}

Eigen::Matrix2Xd refineInRegion(const DescentRefiner& refiner, const cv::Mat& regionGrey,
                                const Eigen::Matrix2Xd& start) {
  Eigen::Matrix2Xd points = start;
  for (const DescentStage& stage : refiner.stages)
    points = applyStage(stage, refiner.meanShape, regionGrey, points);
  return points;
}

Eigen::Matrix2Xd refineInRegion(const DescentRefiner& refiner, const cv::Mat& regionGrey,
                                const Eigen::Matrix2Xd& start, const RefinerStarts& starts) {
  Eigen::Matrix2Xd sum = refineInRegion(refiner, regionGrey, start);
  const int extra = std::max(0, starts.extra);
  if (extra == 0) return sum;
  const double eyeDistance = (start.col(refiner.leftEye) - start.col(refiner.rightEye)).norm();
  const Eigen::Vector2d centroid = start.rowwise().mean();
  for (int k = 0; k < extra; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / extra;
    const double scale = k % 2 == 0 ? 1.0 + starts.spread : 1.0 - starts.spread;
    const Eigen::Vector2d shift =
        starts.spread * eyeDistance * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const Eigen::Matrix2Xd moved =
        (((start.colwise() - centroid) * scale).colwise() + centroid).colwise() + shift;
    sum += refineInRegion(refiner, regionGrey, moved);
  }
  return sum / static_cast<double>(extra + 1);
}

RefinedPoints refineAndCheck(const DescentRefiner& refiner, const cv::Mat& image,
                             const Eigen::Matrix2Xd& points, bool check,
                             const RefinerStarts& starts) {
  RefinedPoints out{points};
  if (refiner.empty()) return out;
  const std::vector<int>& landmarks = refiner.landmarks;
  Eigen::Matrix2Xd start(2, static_cast<Eigen::Index>(landmarks.size()));
  for (std::size_t i = 0; i < landmarks.size(); ++i) {
    if (landmarks[i] >= points.cols()) throw Error("refine: fewer points than the refiner's");
    start.col(static_cast<Eigen::Index>(i)) = points.col(landmarks[i]);
  }
  if (!start.allFinite()) return out;
  const DescentRegion region = descentRegion(image, start, refiner.leftEye, refiner.rightEye);
  const Eigen::Matrix2Xd refinedInRegion =
      refineInRegion(refiner, region.grey, region.toRegion(start), starts);
  if (check) out.rightProbability = checkInRegion(refiner, region.grey, refinedInRegion);
  const Eigen::Matrix2Xd refined = region.toImage(refinedInRegion);
  for (std::size_t i = 0; i < landmarks.size(); ++i)
    out.points.col(landmarks[i]) = refined.col(static_cast<Eigen::Index>(i));
  return out;
}

std::vector<double> descentWindows(int stages, double last, double growth) {
  std::vector<double> windows;
  for (int stage = 0; stage < stages; ++stage) {
    windows.push_back(last * std::pow(growth, stages - 1 - stage));
  }
  return windows;
}

DescentRefiner trainDescentRefiner(const std::vector<DescentPhoto>& photos,
                                   const std::vector<int>& landmarks, int leftEye, int rightEye,
                                   const DescentTrainSettings& settings,
                                   const CancelToken* cancel) {
  if (photos.empty()) throw InputError("refiner: no photos to train from");
  if (settings.startsPerPhoto < 1) throw InputError("refiner: need at least one start per photo");
  DescentRefiner refiner;
  refiner.landmarks = landmarks;
  refiner.leftEye = leftEye;
  refiner.rightEye = rightEye;
  refiner.meanShape = meanShapeOf(photos, leftEye, rightEye);
  const auto n = refiner.meanShape.cols();
  const Eigen::Index d = n * kDescentFeaturesPerPoint;
  // The image's features, then (with shape terms) the scaled departures from the mean shape.
  const Eigen::Index shapeRows = settings.shapeTerms ? 2 * n : 0;
  const int perPhoto = settings.startsPerPhoto;
  const int m = static_cast<int>(photos.size()) * perPhoto;

  std::vector<Eigen::Matrix2Xd> starts = drawStarts(
      photos, leftEye, rightEye, perPhoto, settings.otherShape, settings.start, settings.seed);
  std::vector<Similarity2> frames;
  for (double window : settings.windows) {
    StageSamples samples = stageSamples(photos, perPhoto, starts, refiner.meanShape, window,
                                        settings.shapeTerms, frames, settings.threads, cancel);
    Eigen::MatrixXf& features = samples.features;
    Eigen::MatrixXf& targets = samples.targets;
    DescentStage stage;
    stage.window = window;
    const Eigen::VectorXf featureMean = features.rowwise().mean();
    features.colwise() -= featureMean;
    stage.bias = targets.rowwise().mean();
    targets.colwise() -= stage.bias;
    const Eigen::MatrixXf weights = ridgeRegression(features, targets, settings.ridge);
    // The next stage learns from the starts this one moved, with the features already computed.
    const Eigen::MatrixXf steps = (weights * features).colwise() + stage.bias;
    for (int s = 0; s < m; ++s) starts[s] = stepped(frames[s], starts[s], steps.col(s));
    stage.featureMean = featureMean.head(d);
    stage.weights = weights.leftCols(d);
    if (shapeRows > 0) {
      // W_s (scale (x - mean) - mean of that) = (scale W_s) (x - mean) - (W_s times that mean).
      stage.shapeWeights = static_cast<float>(kShapeFeatureScale) * weights.rightCols(shapeRows);
      stage.bias -= weights.rightCols(shapeRows) * featureMean.tail(shapeRows);
    }
    refiner.stages.push_back(std::move(stage));
  }
  return refiner;
}

DescentRefiner adaptDescentRefiner(const DescentRefiner& general,
                                   const std::vector<DescentPhoto>& photos,
                                   const DescentAdaptSettings& settings,
                                   const CancelToken* cancel) {
  if (general.empty()) return general;
  if (photos.empty()) throw InputError("refiner: no photos to adapt to");
  if (settings.startsPerPhoto < 1) throw InputError("refiner: need at least one start per photo");
  if (!(settings.prior > 0.0)) throw InputError("refiner: the adaptation's prior must be positive");
  DescentRefiner adapted = general;
  const auto n = general.meanShape.cols();
  const Eigen::Index d = n * kDescentFeaturesPerPoint;
  const bool shapeTerms = general.hasShapeWeights();
  const Eigen::Index shapeRows = shapeTerms ? 2 * n : 0;
  const int perPhoto = settings.startsPerPhoto;
  const auto copies = static_cast<double>(photos.size());
  // The general stage weighs as `prior` photos: ridge prior / photos on the residual's regression
  // (the ridge's unit is the samples' mean energy, and each photo gives perPhoto samples), and
  // the residual's mean shrunk by photos / (photos + prior).
  const double ridge = settings.prior / copies;
  const float meanShare = static_cast<float>(copies / (copies + settings.prior));
  std::vector<Eigen::Matrix2Xd> starts =
      drawStarts(photos, general.leftEye, general.rightEye, perPhoto, settings.otherShape,
                 settings.start, settings.seed);
  std::vector<Similarity2> frames;
  for (DescentStage& stage : adapted.stages) {
    StageSamples samples = stageSamples(photos, perPhoto, starts, general.meanShape, stage.window,
                                        shapeTerms, frames, settings.threads, cancel);
    // What the general stage leaves of each step: the residual the video's own regression learns.
    Eigen::MatrixXf predicted =
        (stage.weights * (samples.features.topRows(d).colwise() - stage.featureMean)).colwise() +
        stage.bias;
    if (shapeRows > 0) {
      predicted += stage.shapeWeights * (samples.features.bottomRows(shapeRows) /
                                         static_cast<float>(kShapeFeatureScale));
    }
    Eigen::MatrixXf residual = samples.targets - predicted;
    Eigen::MatrixXf& features = samples.features;
    const Eigen::VectorXf featureMean = features.rowwise().mean();
    features.colwise() -= featureMean;
    const Eigen::VectorXf fullMean = residual.rowwise().mean();
    residual.colwise() -= fullMean;
    const Eigen::VectorXf residualMean = meanShare * fullMean;
    const Eigen::MatrixXf change = ridgeRegression(features, residual, ridge);
    // The next stage adapts from the starts this one moves.
    const Eigen::MatrixXf steps = predicted + ((change * features).colwise() + residualMean);
    for (std::size_t s = 0; s < starts.size(); ++s) {
      starts[s] = stepped(frames[s], starts[s], steps.col(static_cast<Eigen::Index>(s)));
    }
    // The stage plus the change: change (x - mean) = change_image (image - general's mean)
    //   - change_image (mean image - general's mean) + (scale change_shape) departure
    //   - change_shape (mean of the scaled departures).
    stage.weights += change.leftCols(d);
    stage.bias += residualMean - change.leftCols(d) * (featureMean.head(d) - stage.featureMean);
    if (shapeRows > 0) {
      stage.shapeWeights += static_cast<float>(kShapeFeatureScale) * change.rightCols(shapeRows);
      stage.bias -= change.rightCols(shapeRows) * featureMean.tail(shapeRows);
    }
  }
  return adapted;
}

std::vector<DescentPhoto> descentPhotoAndMirror(const cv::Mat& image, const Eigen::Matrix2Xd& truth,
                                                const std::vector<int>& mirror, int leftEye,
                                                int rightEye) {
  if (mirror.size() != static_cast<std::size_t>(truth.cols()) ||
      std::any_of(mirror.begin(), mirror.end(),
                  [&](int m) { return m < 0 || m >= truth.cols(); })) {
    throw Error("refine: a point's mirror image is not among the refined points");
  }
  if (image.empty() || !truth.allFinite() ||
      (truth.col(leftEye) - truth.col(rightEye)).norm() < 1.0)
    return {};
  cv::Mat flipped;
  cv::flip(image, flipped, 1);
  Eigen::Matrix2Xd mirrored(2, truth.cols());
  for (Eigen::Index i = 0; i < truth.cols(); ++i) {
    mirrored.col(mirror[static_cast<std::size_t>(i)]) =
        Eigen::Vector2d(image.cols - 1 - truth(0, i), truth(1, i));
  }
  std::vector<DescentPhoto> faces(2);
  for (int side = 0; side < 2; ++side) {
    const Eigen::Matrix2Xd& points = side == 0 ? truth : mirrored;
    faces[static_cast<std::size_t>(side)].region =
        descentRegion(side == 0 ? image : flipped, points, leftEye, rightEye);
    faces[static_cast<std::size_t>(side)].truth =
        faces[static_cast<std::size_t>(side)].region.toRegion(points);
  }
  return faces;
}

}  // namespace clm3d
