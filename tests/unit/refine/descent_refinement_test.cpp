// Tests of the point refiner (core/refine): on drawn "faces" (dark discs of different sizes at
// known points over a noisy background, each face moved, scaled and turned at random), a cascade
// trained on some faces brings perturbed starts on other faces much closer to the truth, and its
// check tells refined points that are right from ones a far start left wrong; an empty refiner or
// a start that is not finite leaves the points as they are; bad images are refused.
#include "core/refine/descent_refinement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <opencv2/imgproc.hpp>
#include <random>

#include "core/common/error.hpp"
#include "core/geometry/similarity2.hpp"
#include "core/refine/descent_check.hpp"

namespace clm3d {
namespace {

// Six points: two "eyes" (0, 1), a nose (2), two mouth corners (3, 4), a chin (5); eye distance 1.
Eigen::Matrix2Xd canonicalFace() {
  Eigen::Matrix2Xd face(2, 6);
  face << -0.5, 0.5, 0.0, -0.4, 0.4, 0.0,  //
      0.0, 0.0, 0.6, 1.0, 1.0, 1.5;
  return face;
}
const double kRadius[6] = {0.14, 0.14, 0.1, 0.08, 0.08, 0.12};

struct DrawnFace {
  cv::Mat image;  // 8-bit grey
  Eigen::Matrix2Xd points;
};

// A face at a random place, size (eye distance 50-90 px) and roll, each point also moved a little.
DrawnFace drawFace(std::mt19937_64& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  DrawnFace face;
  face.image = cv::Mat(320, 320, CV_8UC1);
  cv::randu(face.image, 150, 200);
  cv::GaussianBlur(face.image, face.image, cv::Size(5, 5), 1.5);
  const double eyeDistance = 50.0 + 40.0 * uniform(random);
  const double roll = 0.3 * (uniform(random) - 0.5);
  const Eigen::Vector2d centre(140.0 + 40.0 * uniform(random), 110.0 + 30.0 * uniform(random));
  const Eigen::Matrix2Xd shape = canonicalFace();
  face.points.resize(2, shape.cols());
  for (Eigen::Index i = 0; i < shape.cols(); ++i) {
    const Eigen::Vector2d p = shape.col(i) + 0.04 * Eigen::Vector2d(normal(random), normal(random));
    face.points.col(i) =
        centre + eyeDistance * Eigen::Vector2d(std::cos(roll) * p.x() - std::sin(roll) * p.y(),
                                               std::sin(roll) * p.x() + std::cos(roll) * p.y());
    cv::circle(face.image, cv::Point2d(face.points(0, i), face.points(1, i)),
               static_cast<int>(std::lround(kRadius[i] * eyeDistance)), cv::Scalar(40), cv::FILLED,
               cv::LINE_AA);
  }
  return face;
}

double meanError(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b) {
  const double eyeDistance = (b.col(0) - b.col(1)).norm();
  return (a - b).colwise().norm().mean() / eyeDistance;
}

// A start as a search leaves it: the truth shifted by 0.1 of the eye distance, scaled by 5%.
Eigen::Matrix2Xd offStart(const Eigen::Matrix2Xd& truth, std::mt19937_64& random) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const double eyeDistance = (truth.col(0) - truth.col(1)).norm();
  const Eigen::Vector2d centre = truth.rowwise().mean();
  const Eigen::Vector2d shift = 0.1 * eyeDistance * Eigen::Vector2d(normal(random), normal(random));
  return ((1.0 + 0.05 * normal(random)) * (truth.colwise() - centre)).colwise() + (centre + shift);
}

const std::vector<int> kLandmarks{3, 4, 5, 6, 7, 8};  // scheme indices, any

// `count` drawn faces as training photos: each cut around its true points.
std::vector<DescentPhoto> drawnPhotos(int count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<DescentPhoto> photos;
  for (int f = 0; f < count; ++f) {
    const DrawnFace face = drawFace(random);
    DescentPhoto photo;
    photo.region = descentRegion(face.image, face.points, 0, 1);
    photo.truth = photo.region.toRegion(face.points);
    photos.push_back(std::move(photo));
  }
  return photos;
}

DescentRefiner trainedRefiner() {
  static const DescentRefiner refiner = [] {
    DescentTrainSettings settings;
    settings.startsPerPhoto = 8;
    settings.threads = 2;
    return trainDescentRefiner(drawnPhotos(80, 11), kLandmarks, 0, 1, settings);
  }();
  return refiner;
}

TEST(DescentRefinement, BringsStartsOnUnseenFacesCloserToTheTruth) {
  const DescentRefiner& refiner = trainedRefiner();
  ASSERT_EQ(refiner.stages.size(), DescentTrainSettings{}.windows.size());
  EXPECT_NO_THROW(refiner.validate(10));
  std::mt19937_64 random(99);
  double before = 0.0, after = 0.0;
  constexpr int kFaces = 30;
  for (int f = 0; f < kFaces; ++f) {
    const DrawnFace face = drawFace(random);
    const Eigen::Matrix2Xd start = offStart(face.points, random);
    // The refiner takes every scheme landmark and moves only its own.
    Eigen::Matrix2Xd all = Eigen::Matrix2Xd::Constant(2, 10, 7.0);
    for (std::size_t i = 0; i < kLandmarks.size(); ++i) all.col(kLandmarks[i]) = start.col(i);
    const Eigen::Matrix2Xd refinedAll = refinePoints(refiner, face.image, all);
    Eigen::Matrix2Xd refined(2, 6);
    for (std::size_t i = 0; i < kLandmarks.size(); ++i)
      refined.col(i) = refinedAll.col(kLandmarks[i]);
    EXPECT_EQ(refinedAll.col(0), Eigen::Vector2d(7.0, 7.0));
    before += meanError(start, face.points) / kFaces;
    after += meanError(refined, face.points) / kFaces;
  }
  EXPECT_GT(before, 0.08);
  EXPECT_LT(after, 0.25 * before) << "before " << before << ", after " << after;
}

// The scheme's points (10) with the refiner's six at `points`, the others at (7, 7).
Eigen::Matrix2Xd schemePoints(const Eigen::Matrix2Xd& points) {
  Eigen::Matrix2Xd all = Eigen::Matrix2Xd::Constant(2, 10, 7.0);
  for (std::size_t i = 0; i < kLandmarks.size(); ++i) all.col(kLandmarks[i]) = points.col(i);
  return all;
}

Eigen::Matrix2Xd refinersPoints(const Eigen::Matrix2Xd& all) {
  Eigen::Matrix2Xd points(2, static_cast<Eigen::Index>(kLandmarks.size()));
  for (std::size_t i = 0; i < kLandmarks.size(); ++i) points.col(i) = all.col(kLandmarks[i]);
  return points;
}

// A search leaves the shape model's idea of the face, not a moved copy of the true one: trained
// with starts taken towards other faces' shapes (otherShape), the cascade is another one, and it
// brings starts with another face's shape on unseen faces close to the truth.
TEST(DescentRefinement, StartsTakenTowardsOtherFacesShapesTrainACascadeThatCorrectsThem) {
  DescentTrainSettings settings;
  settings.startsPerPhoto = 8;
  settings.threads = 2;
  settings.otherShape = 1.0;
  const DescentRefiner refiner =
      trainDescentRefiner(drawnPhotos(80, 11), kLandmarks, 0, 1, settings);
  ASSERT_EQ(refiner.stages.size(), trainedRefiner().stages.size());
  EXPECT_FALSE(refiner.stages.front().weights.isApprox(trainedRefiner().stages.front().weights));

  std::mt19937_64 random(7);
  double before = 0.0, after = 0.0;
  constexpr int kFaces = 30;
  for (int f = 0; f < kFaces; ++f) {
    const DrawnFace face = drawFace(random);
    // Another face's shape, brought onto this one's place, size and roll, is the start's shape.
    const Eigen::Matrix2Xd other = drawFace(random).points;
    const Eigen::Matrix2Xd start =
        offStart(alignSimilarity2(other, face.points).apply(other), random);
    const Eigen::Matrix2Xd refined =
        refinersPoints(refinePoints(refiner, face.image, schemePoints(start)));
    before += meanError(start, face.points) / kFaces;
    after += meanError(refined, face.points) / kFaces;
  }
  EXPECT_GT(before, 0.08);
  EXPECT_LT(after, 0.25 * before) << "before " << before << ", after " << after;
}

// Adapting to one video's mark-up (adaptDescentRefiner): a "video" whose annotator puts the chin
// (point 5) 0.15 eye distances below the disc the general refiner learnt. Adapted on 12 of its
// faces (and their mirror images), the cascade puts the chin of 20 other faces of the video near
// the annotator's place, the other points as well as before; with an overwhelming prior it stays
// the general one; the same photos and seed give the same cascade whatever the thread count.
TEST(DescentRefinement, AdaptingToAVideosMarkupLearnsItsOffsetWithoutForgetting) {
  const DescentRefiner& general = trainedRefiner();
  constexpr double kChinOffset = 0.15;
  const auto annotated = [&](const DrawnFace& face) {
    Eigen::Matrix2Xd points = face.points;
    points(1, 5) += kChinOffset * (points.col(0) - points.col(1)).norm();
    return points;
  };
  const std::vector<int> mirror{1, 0, 2, 4, 3, 5};
  std::mt19937_64 random(31);
  std::vector<DescentPhoto> video;
  for (int f = 0; f < 12; ++f) {
    const DrawnFace face = drawFace(random);
    for (DescentPhoto& photo : descentPhotoAndMirror(face.image, annotated(face), mirror, 0, 1)) {
      video.push_back(std::move(photo));
    }
  }
  ASSERT_EQ(video.size(), 24u);
  DescentAdaptSettings settings;
  settings.startsPerPhoto = 8;
  settings.threads = 2;
  const DescentRefiner adapted = adaptDescentRefiner(general, video, settings);
  ASSERT_EQ(adapted.stages.size(), general.stages.size());
  EXPECT_NO_THROW(adapted.validate(10));
  EXPECT_EQ(adapted.meanShape, general.meanShape);

  double chinGeneral = 0.0, chinAdapted = 0.0, restGeneral = 0.0, restAdapted = 0.0;
  constexpr int kFaces = 20;
  for (int f = 0; f < kFaces; ++f) {
    const DrawnFace face = drawFace(random);
    const Eigen::Matrix2Xd truth = annotated(face);
    const Eigen::Matrix2Xd start = offStart(truth, random);
    const double eyes = (truth.col(0) - truth.col(1)).norm();
    const Eigen::Matrix2Xd byGeneral =
        refinersPoints(refinePoints(general, face.image, schemePoints(start)));
    const Eigen::Matrix2Xd byAdapted =
        refinersPoints(refinePoints(adapted, face.image, schemePoints(start)));
    chinGeneral += (byGeneral.col(5) - truth.col(5)).norm() / eyes / kFaces;
    chinAdapted += (byAdapted.col(5) - truth.col(5)).norm() / eyes / kFaces;
    restGeneral += meanError(byGeneral.leftCols(5), truth.leftCols(5)) / kFaces;
    restAdapted += meanError(byAdapted.leftCols(5), truth.leftCols(5)) / kFaces;
  }
  std::cout << "[ chin " << chinGeneral << " -> " << chinAdapted << ", other points " << restGeneral
            << " -> " << restAdapted << " ]\n";
  EXPECT_GT(chinGeneral, 0.1);
  EXPECT_LT(chinAdapted, 0.5 * chinGeneral);
  EXPECT_LT(restAdapted, 1.2 * restGeneral + 0.005);

  DescentAdaptSettings heavy = settings;
  heavy.prior = 1e6;
  const DescentRefiner kept = adaptDescentRefiner(general, video, heavy);
  for (std::size_t k = 0; k < kept.stages.size(); ++k) {
    EXPECT_LT((kept.stages[k].bias - general.stages[k].bias).cwiseAbs().maxCoeff(), 1e-3) << k;
  }
  DescentAdaptSettings oneThread = settings;
  oneThread.threads = 1;
  const DescentRefiner again = adaptDescentRefiner(general, video, oneThread);
  for (std::size_t k = 0; k < again.stages.size(); ++k) {
    EXPECT_EQ(again.stages[k].weights, adapted.stages[k].weights) << k;
    EXPECT_EQ(again.stages[k].bias, adapted.stages[k].bias) << k;
  }
  EXPECT_THROW(adaptDescentRefiner(general, {}, settings), InputError);
  const DrawnFace face = drawFace(random);
  EXPECT_THROW(descentPhotoAndMirror(face.image, face.points, {1, 0, 2, 4, 3, 6}, 0, 1), Error);
  EXPECT_THROW(descentPhotoAndMirror(face.image, face.points, {1, 0}, 0, 1), Error);
}

TEST(DescentCheck, TellsRightRefinedPointsFromWrongOnes) {
  DescentRefiner refiner = trainedRefiner();
  DescentCheckSettings settings;
  settings.threads = 2;
  refiner.check = trainDescentCheck(drawnPhotos(80, 11), refiner, settings);
  EXPECT_NO_THROW(refiner.validate(10));
  // Unseen faces from near starts (as a search leaves them) and far ones (the face missed by most
  // of an eye distance): each refined, then judged right or wrong by its own error.
  std::mt19937_64 random(123);
  std::vector<double> right, wrong;
  for (int f = 0; f < 40; ++f) {
    const DrawnFace face = drawFace(random);
    const double eyes = (face.points.col(0) - face.points.col(1)).norm();
    for (const bool far : {false, true}) {
      Eigen::Matrix2Xd start = offStart(face.points, random);
      if (far) start.colwise() += Eigen::Vector2d(0.6, 0.5) * eyes * (f % 2 == 0 ? 1.0 : -1.0);
      const RefinedPoints refined = refineAndCheck(refiner, face.image, schemePoints(start));
      ASSERT_TRUE(std::isfinite(refined.rightProbability));
      EXPECT_GE(refined.rightProbability, 0.0);
      EXPECT_LE(refined.rightProbability, 1.0);
      const double error = meanError(refinersPoints(refined.points), face.points);
      if (error < 0.15) right.push_back(refined.rightProbability);
      if (error > 0.3) wrong.push_back(refined.rightProbability);
      EXPECT_EQ(refined.points,
                refineAndCheck(refiner, face.image, schemePoints(start), false).points);
    }
  }
  ASSERT_GE(right.size(), 20u);
  ASSERT_GE(wrong.size(), 20u);
  // The share of (right, wrong) pairs the check orders correctly: the ROC's area.
  double ordered = 0.0;
  for (double r : right) {
    for (double w : wrong) ordered += r > w ? 1.0 : r == w ? 0.5 : 0.0;
  }
  const double auc = ordered / static_cast<double>(right.size() * wrong.size());
  EXPECT_GT(auc, 0.95) << right.size() << " right, " << wrong.size() << " wrong";
  const auto above = [](const std::vector<double>& p) {
    return std::count_if(p.begin(), p.end(), [](double x) { return x > 0.5; });
  };
  EXPECT_GE(above(right), static_cast<long>(0.9 * right.size()));
  EXPECT_LE(above(wrong), static_cast<long>(0.1 * wrong.size()));

  // Without a check: no probability.
  EXPECT_TRUE(std::isnan(
      refineAndCheck(trainedRefiner(), drawFace(random).image, schemePoints(canonicalFace() * 50.0))
          .rightProbability));
  DescentRefiner broken = refiner;
  broken.check.weights.resize(5);
  EXPECT_THROW(broken.validate(10), Error);
  EXPECT_THROW(trainDescentCheck(drawnPhotos(4, 3), refiner, settings), InputError);
}

// Refining from several starts: the mean of the cascade's runs from the start and from its copies
// moved spread eye distances round a circle and scaled alternately up and down by spread; 0 extra
// starts is the start alone, and the averaged points still land on the face.
TEST(DescentRefinement, MoreStartsAverageTheRunsFromCopiesMovedAroundTheStart) {
  const DescentRefiner& refiner = trainedRefiner();
  std::mt19937_64 random(31);
  const DrawnFace face = drawFace(random);
  const Eigen::Matrix2Xd start = offStart(face.points, random);
  const DescentRegion region = descentRegion(face.image, start, 0, 1);
  const Eigen::Matrix2Xd inRegion = region.toRegion(start);
  EXPECT_EQ(refineInRegion(refiner, region.grey, inRegion, RefinerStarts{0, 0.04}),
            refineInRegion(refiner, region.grey, inRegion));

  const RefinerStarts starts{4, 0.05};
  const double eyes = (inRegion.col(0) - inRegion.col(1)).norm();
  const Eigen::Vector2d centroid = inRegion.rowwise().mean();
  const Eigen::Vector2d shifts[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  const double scales[4] = {1.05, 0.95, 1.05, 0.95};
  Eigen::Matrix2Xd sum = refineInRegion(refiner, region.grey, inRegion);
  for (int k = 0; k < 4; ++k) {
    const Eigen::Matrix2Xd moved = ((inRegion.colwise() - centroid) * scales[k]).colwise() +
                                   (centroid + 0.05 * eyes * shifts[k]);
    sum += refineInRegion(refiner, region.grey, moved);
  }
  const Eigen::Matrix2Xd averaged = refineInRegion(refiner, region.grey, inRegion, starts);
  EXPECT_TRUE(averaged.isApprox(sum / 5.0, 1e-9));
  EXPECT_FALSE(averaged.isApprox(refineInRegion(refiner, region.grey, inRegion), 1e-6));

  const Eigen::Matrix2Xd refined = refinersPoints(
      refineAndCheck(refiner, face.image, schemePoints(start), false, starts).points);
  EXPECT_TRUE(refined.isApprox(region.toImage(averaged), 1e-9));
  EXPECT_LT(meanError(refined, face.points), 0.5 * meanError(start, face.points));
}

TEST(DescentRefinement, TrainingDoesNotDependOnTheThreadCount) {
  const std::vector<DescentPhoto> photos = drawnPhotos(6, 5);
  DescentTrainSettings settings;
  settings.windows = {0.6};
  settings.startsPerPhoto = 3;
  settings.threads = 1;
  const DescentRefiner one = trainDescentRefiner(photos, kLandmarks, 0, 1, settings);
  settings.threads = 2;
  const DescentRefiner two = trainDescentRefiner(photos, kLandmarks, 0, 1, settings);
  EXPECT_TRUE(one.stages[0].weights.isApprox(two.stages[0].weights));
  EXPECT_EQ(one.meanShape, two.meanShape);
}

TEST(DescentCheck, TrainingDoesNotDependOnTheThreadCount) {
  const std::vector<DescentPhoto> photos = drawnPhotos(60, 17);
  DescentCheckSettings settings;
  settings.threads = 1;
  const DescentCheck one = trainDescentCheck(photos, trainedRefiner(), settings);
  settings.threads = 2;
  const DescentCheck two = trainDescentCheck(photos, trainedRefiner(), settings);
  EXPECT_EQ(one.weights, two.weights);
  EXPECT_EQ(one.slope, two.slope);
  EXPECT_EQ(one.offset, two.offset);
}

TEST(DescentRefinement, EmptyRefinerOrNonFiniteStartLeavesThePointsAlone) {
  const cv::Mat image(100, 100, CV_8UC1, cv::Scalar(128));
  Eigen::Matrix2Xd points =
      Eigen::Matrix2Xd::Random(2, 10) * 20.0 + Eigen::Matrix2Xd::Constant(2, 10, 50.0);
  EXPECT_EQ(refinePoints(DescentRefiner{}, image, points), points);
  points(0, kLandmarks[2]) = std::nan("");
  const Eigen::Matrix2Xd out = refinePoints(trainedRefiner(), image, points);
  EXPECT_TRUE(out.cwiseEqual(points).count() + 1 == points.size());  // the NaN is unequal to itself
}

TEST(DescentRefinement, BadImagesAndPointsAreRefused) {
  const Eigen::Matrix2Xd points = canonicalFace() * 50.0;
  EXPECT_THROW(descentRegion(cv::Mat(), points, 0, 1), InputError);
  EXPECT_THROW(descentRegion(cv::Mat(50, 50, CV_16UC1), points, 0, 1), InputError);
  Eigen::Matrix2Xd sameEyes = points;
  sameEyes.col(1) = sameEyes.col(0);
  EXPECT_THROW(descentRegion(cv::Mat(50, 50, CV_8UC1), sameEyes, 0, 1), InputError);
  DescentRefiner broken = trainedRefiner();
  broken.stages[0].bias.resize(3);
  EXPECT_THROW(broken.validate(10), Error);
  broken = trainedRefiner();
  EXPECT_THROW(broken.validate(5), Error);  // landmark 8 is not in a 5-point scheme
}

}  // namespace
}  // namespace clm3d
