// The point-file error: eq. 5.1 over a chosen subset, normalised by the true eye-centre distance,
// with missing points, 68-point truths and bad point lists.
#include "core/eval/point_set_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/common/error.hpp"
#include "core/scheme/landmark_file.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// thesis25 points on a grid, eye centres (points 8 and 11, 0-based 7 and 10) 50 pixels apart.
LandmarkSet face() {
  LandmarkSet set(25, 2);
  for (int i = 0; i < 25; ++i) set.set(i, Eigen::Vector2d(100.0 + 7.0 * i, 200.0 + 3.0 * (i % 4)));
  set.set(7, Eigen::Vector2d(175.0, 150.0));
  set.set(10, Eigen::Vector2d(125.0, 150.0));
  return set;
}

TEST(PointList, NumbersRangesAndIdsAreOneBasedSortedAndDistinct) {
  const auto& scheme = Scheme::thesis25();
  EXPECT_EQ(parsePointList("1-3, 22,2", scheme), (std::vector<int>{0, 1, 2, 21}));
  EXPECT_EQ(parsePointList("nose_tip,1", scheme),
            (std::vector<int>{0, scheme.indexOf("nose_tip")}));
  EXPECT_EQ(parsePointList("1-18,22", scheme).size(), 19u);
}

TEST(PointList, BadItemsAreNamed) {
  const auto& scheme = Scheme::thesis25();
  const auto message = [&](const char* text) {
    try {
      parsePointList(text, scheme);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("0").find("'0' is not in 1-25"), std::string::npos) << message("0");
  EXPECT_NE(message("26").find("'26' is not in 1-25"), std::string::npos);
  EXPECT_NE(message("5-2").find("range '5-2' ends before it starts"), std::string::npos);
  EXPECT_NE(message("nose").find("has no point 'nose'"), std::string::npos);
  EXPECT_NE(message("1,,2").find("empty item"), std::string::npos);
  EXPECT_NE(message("").find("empty item"), std::string::npos);
}

TEST(PointSetError, MeanOverSelectedPointsNormalisedByTrueEyeDistance) {
  const auto& scheme = Scheme::thesis25();
  const auto truth = face();
  auto prediction = truth;
  prediction.set(0, Eigen::Vector2d(truth.point(0).x() + 10.0, truth.point(0).y()));     // 0.2
  prediction.set(1, Eigen::Vector2d(truth.point(1).x(), truth.point(1).y() - 5.0));      // 0.1
  prediction.set(20, Eigen::Vector2d(truth.point(20).x() + 50.0, truth.point(20).y()));  // 1.0

  const auto all = evaluatePointSet(truth, prediction, scheme, {});
  EXPECT_DOUBLE_EQ(all.interOcular, 50.0);
  EXPECT_EQ(all.scoredPoints, 25);
  EXPECT_NEAR(all.error, (0.2 + 0.1 + 1.0) / 25.0, 1e-12);
  EXPECT_NEAR(all.maxError, 1.0, 1e-12);
  EXPECT_EQ(all.foundPoints, 23);  // 0.2 and 1.0 are above 0.18

  // Point 21 (0-based 20) not selected: it no longer counts.
  const auto some = evaluatePointSet(truth, prediction, scheme, {0, 1, 2, 3});
  EXPECT_EQ(some.selected, 4);
  EXPECT_EQ(some.scoredPoints, 4);
  EXPECT_NEAR(some.error, 0.3 / 4.0, 1e-12);
  EXPECT_TRUE(std::isnan(some.pointErrors[20]));
  EXPECT_NEAR(some.pointErrors[0], 0.2, 1e-12);
}

TEST(PointSetError, MissingPointsAreNotScoredAndMissingEyesAreAnError) {
  const auto& scheme = Scheme::thesis25();
  auto truth = face();
  auto prediction = face();
  truth.setMissing(18);      // earlobe: not in the truth
  prediction.setMissing(3);  // not predicted
  const auto result = evaluatePointSet(truth, prediction, scheme, {});
  EXPECT_EQ(result.truePoints, 24);
  EXPECT_EQ(result.scoredPoints, 23);
  EXPECT_DOUBLE_EQ(result.error, 0.0);

  truth.setMissing(7);
  EXPECT_THROW(evaluatePointSet(truth, prediction, scheme, {}), std::invalid_argument);
  auto nothing = face();
  for (int i = 0; i < 25; ++i) nothing.setMissing(i);
  const auto none = evaluatePointSet(face(), nothing, scheme, {});
  EXPECT_TRUE(std::isnan(none.error));
  EXPECT_EQ(none.scoredPoints, 0);
}

TEST(PointSetError, FilesWithA68PointTruthAndJsonReport) {
  const auto& scheme = Scheme::thesis25();
  test::TempDir dir;
  // A 68-point mark-up: the eye contours give the eye centres (thesis 8 and 11).
  LandmarkSet ibug(68, 2);
  for (int i = 0; i < 68; ++i) ibug.set(i, Eigen::Vector2d(50.0 + 3.0 * i, 80.0 + (i % 7)));
  for (int i = 36; i < 42; ++i) ibug.set(i, Eigen::Vector2d(100.0 + (i - 36), 60.0));
  for (int i = 42; i < 48; ++i) ibug.set(i, Eigen::Vector2d(160.0 + (i - 42), 60.0));
  writeLandmarks(dir / "truth.pts", ibug, Scheme::ibug68());
  const auto converted = readLandmarks(dir / "truth.pts", &scheme);
  auto shifted = converted;
  for (int i = 0; i < 25; ++i) {
    if (shifted.has(i))
      shifted.set(i, Eigen::Vector2d(shifted.point(i).head<2>() + Eigen::Vector2d(6.0, 0.0)));
  }
  writeLandmarks(dir / "fit.pts", shifted, scheme);

  const auto report = evaluatePointFiles(dir / "truth.pts", {dir / "fit.pts"}, {"fit"}, scheme,
                                         parsePointList("1-18,22", scheme));
  ASSERT_EQ(report.results.size(), 1u);
  const auto& r = report.results[0];
  EXPECT_NEAR(r.interOcular, 60.0, 1e-9);
  EXPECT_EQ(r.truePoints, 19);
  EXPECT_NEAR(r.error, 0.1, 1e-9);
  EXPECT_EQ(r.label, "fit");

  const auto json = nlohmann::json::parse(formatPointReportJson(report));
  EXPECT_EQ(json["format"], "clm3d-point-evaluation");
  EXPECT_EQ(json["points"].size(), 19u);
  EXPECT_EQ(json["points"][18], 22);
  EXPECT_NEAR(json["predictions"][0]["error"].get<double>(), 0.1, 1e-9);
  EXPECT_TRUE(json["predictions"][0]["point_errors"][18].is_null());  // an earlobe
  EXPECT_NE(formatPointReportText(report).find("fit ("), std::string::npos);
  EXPECT_NE(formatPointReportText(report).find("error 0.1000 over 19/19 points"), std::string::npos)
      << formatPointReportText(report);
}

TEST(PointSetError, FileErrorsNameTheFile) {
  const auto& scheme = Scheme::thesis25();
  test::TempDir dir;
  auto truth = face();
  truth.setMissing(10);
  writeLandmarks(dir / "noeye.pts", truth, scheme);
  writeLandmarks(dir / "fit.pts", face(), scheme);
  try {
    evaluatePointFiles(dir / "noeye.pts", {dir / "fit.pts"}, {}, scheme, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("noeye.pts: no usable normalisation pair"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(evaluatePointFiles(dir / "fit.pts", {dir / "absent.pts"}, {}, scheme, {}),
               InputError);
  EXPECT_THROW(evaluatePointFiles(dir / "fit.pts", {dir / "fit.pts"}, {"a", "b"}, scheme, {}),
               InputError);
}

// Box normalisation on a hand-made truth: four present points spanning x 90..150 and y 80..160,
// a box of 60 x 80 pixels whatever points are selected.
TEST(PointSetError, BoxNormalisedErrorDividesTheMeanPixelErrorBySqrtOfTheTruthBoxArea) {
  const auto& scheme = Scheme::thesis25();
  LandmarkSet truth(25, 2);
  truth.set(7, Eigen::Vector2d(130.0, 100.0));  // eye centres 30 pixels apart
  truth.set(10, Eigen::Vector2d(100.0, 100.0));
  truth.set(0, Eigen::Vector2d(90.0, 80.0));
  truth.set(20, Eigen::Vector2d(150.0, 160.0));
  LandmarkSet prediction = truth;
  prediction.set(0, Eigen::Vector2d(96.0, 80.0));    // 6 pixels off
  prediction.setMissing(20);                         // not scored, still in the truth's box
  prediction.set(3, Eigen::Vector2d(900.0, 900.0));  // not in the truth: not scored
  const auto r = evaluatePointSet(truth, prediction, scheme, {});
  EXPECT_EQ(r.truePoints, 4);
  EXPECT_EQ(r.scoredPoints, 3);
  EXPECT_NEAR(r.boxSize, std::sqrt(60.0 * 80.0), 1e-9);
  // 6 pixels over 3 scored points = 2 pixels; over the eye distance 30 and over the box.
  EXPECT_NEAR(r.error, 2.0 / 30.0, 1e-12);
  EXPECT_NEAR(r.boxError, 2.0 / std::sqrt(4800.0), 1e-12);
  // Selecting one point changes the mean but not the box.
  const auto one = evaluatePointSet(truth, prediction, scheme, {0});
  EXPECT_NEAR(one.boxSize, std::sqrt(4800.0), 1e-9);
  EXPECT_NEAR(one.boxError, 6.0 / std::sqrt(4800.0), 1e-12);
}

}  // namespace
}  // namespace clm3d
