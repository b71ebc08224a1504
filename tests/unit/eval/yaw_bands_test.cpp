// Pose-aware folder evaluation: AFLW's "-1 -1" invisible points left out of the scores and the
// box, band assignment from a poses CSV in AFLW's index.csv layout, rejected fits (summary.csv)
// not fitted, and the CSV and edge errors.
#include "core/eval/yaw_bands.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/common/error.hpp"
#include "core/eval/point_folder_error.hpp"
#include "core/scheme/landmark_file.hpp"
#include "tests/support/test_files.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

// A thesis25 .pts written by hand, AFLW-style: four marked points (1-based on disk), the other 21
// "-1 -1". In memory: 7 -> (130, 100), 10 -> (100, 100), 0 -> (90, 80), 20 -> (150, 160).
std::string handTruthPts() {
  std::ostringstream out;
  out << "version: 1\nn_points: 25\n{\n";
  for (int i = 0; i < 25; ++i) {
    if (i == 7)
      out << "131 101\n";
    else if (i == 10)
      out << "101 101\n";
    else if (i == 0)
      out << "91 81\n";
    else if (i == 20)
      out << "151 161\n";
    else
      out << "-1 -1\n";
  }
  out << "}\n";
  return out.str();
}

// A prediction: the four marked points, point 0 moved by dx, every other point far off.
LandmarkSet handPrediction(double dx) {
  LandmarkSet set(25, 2);
  for (int i = 0; i < 25; ++i) set.set(i, Eigen::Vector2d(500.0, 500.0));
  set.set(7, Eigen::Vector2d(130.0, 100.0));
  set.set(10, Eigen::Vector2d(100.0, 100.0));
  set.set(0, Eigen::Vector2d(90.0 + dx, 80.0));
  set.set(20, Eigen::Vector2d(150.0, 160.0));
  return set;
}

TEST(YawBands, BandOfAbsoluteYawWithTheLastBandClosed) {
  const std::vector<double> edges{0.0, 30.0, 60.0, 90.0};
  EXPECT_EQ(yawBandOf(0.0, edges), 0);
  EXPECT_EQ(yawBandOf(-29.9, edges), 0);
  EXPECT_EQ(yawBandOf(30.0, edges), 1);
  EXPECT_EQ(yawBandOf(-60.0, edges), 2);
  EXPECT_EQ(yawBandOf(90.0, edges), 2);
  EXPECT_EQ(yawBandOf(90.5, edges), -1);
  EXPECT_EQ(yawBandOf(std::numeric_limits<double>::quiet_NaN(), edges), -1);
  EXPECT_EQ(parseBandEdges("0,45,90"), (std::vector<double>{0.0, 45.0, 90.0}));
  EXPECT_THROW(parseBandEdges("30"), InputError);
  EXPECT_THROW(parseBandEdges("0,60,30"), InputError);
  EXPECT_THROW(parseBandEdges("-10,30"), InputError);
  EXPECT_THROW(parseBandEdges("0,x"), InputError);
}

TEST(YawBands, InvisibleMarksAreMissingInScoresAndBox) {
  test::TempDir dir;
  const fs::path truth = dir / "truth";
  const fs::path fits = dir / "fits";
  fs::create_directories(truth);
  fs::create_directories(fits);
  test::writeFile(truth / "a.pts", handTruthPts());
  writeLandmarks(fits / "a.pts", handPrediction(6.0), Scheme::thesis25());
  const auto report = evaluatePointFolders(truth, {fits}, {}, Scheme::thesis25(), {});
  EXPECT_EQ(report.truePoints[0], 4);
  const auto& r = *report.methods[0].results[0];
  EXPECT_EQ(r.scoredPoints, 4);
  EXPECT_NEAR(r.error, 6.0 / 4.0 / 30.0, 1e-12);  // 1.5 pixels over the 30-pixel eye distance
  EXPECT_NEAR(r.boxSize, std::sqrt(60.0 * 80.0), 1e-9);
  EXPECT_NEAR(report.methods[0].meanBoxError, 1.5 / std::sqrt(4800.0), 1e-12);
  EXPECT_NE(formatPointFolderCsv(report).find(",4,4,3,30.000,0.021651,69.282,,"), std::string::npos)
      << formatPointFolderCsv(report);
}

TEST(YawBands, BandsFromAnAflwStylePosesCsvWithRejectedAndMissingFits) {
  test::TempDir dir;
  const fs::path truth = dir / "truth";
  const fs::path fits = dir / "fits";
  fs::create_directories(truth);
  fs::create_directories(fits);
  for (const char* stem : {"a", "b", "c", "d"}) {
    test::writeFile(truth / (std::string(stem) + ".pts"), handTruthPts());
  }
  writeLandmarks(fits / "a.pts", handPrediction(6.0), Scheme::thesis25());   // fitted
  writeLandmarks(fits / "b.pts", handPrediction(0.0), Scheme::thesis25());   // kept, rejected
  writeLandmarks(fits / "d.pts", handPrediction(12.0), Scheme::thesis25());  // no yaw
  test::writeFile(fits / "summary.csv",
                  "image,status,confidence\nimg/a.png,ok,0.9\nimg/b.png,rejected,0.1\n");
  const fs::path poses = dir / "index.csv";
  test::writeFile(poses,
                  "image,yaw_deg,visible_count,split\nimages/a.jpg,-10.00,4,test\n"
                  "images/b.jpg,45.5,4,test\nimages/c.jpg,75.00,4,test\nimages/e.jpg,5,4,train\n");
  auto report = evaluatePointFolders(truth, {fits}, {}, Scheme::thesis25(), {});
  const auto yaws = yawsByStem(report, readPoseCsv(poses));
  ASSERT_EQ(yaws.size(), 4U);
  EXPECT_DOUBLE_EQ(yaws[0], -10.0);
  EXPECT_DOUBLE_EQ(yaws[1], 45.5);
  EXPECT_TRUE(std::isnan(yaws[3]));
  addYawBands(report, yaws, {0.0, 30.0, 60.0, 90.0}, "test poses");
  const auto& bands = report.methods[0].bands;
  ASSERT_EQ(bands.size(), 3U);
  EXPECT_EQ(bands[0].faces, 1);
  EXPECT_EQ(bands[0].fitted, 1);
  EXPECT_NEAR(bands[0].meanBoxError, 1.5 / std::sqrt(4800.0), 1e-12);
  EXPECT_NEAR(bands[0].meanEyeError, 0.05, 1e-12);
  EXPECT_EQ(bands[0].foundPoints, 3);  // point 0 is 0.2 eye distances off, above 0.18
  EXPECT_NEAR(bands[0].foundShare, 0.75, 1e-12);
  EXPECT_EQ(bands[1].faces, 1);  // b: a prediction, but rejected
  EXPECT_EQ(bands[1].fitted, 0);
  EXPECT_TRUE(std::isnan(bands[1].meanBoxError));
  EXPECT_EQ(bands[1].foundPoints, 0);
  EXPECT_EQ(bands[1].truePoints, 4);
  EXPECT_EQ(bands[2].faces, 1);  // c: no prediction
  EXPECT_EQ(bands[2].fitted, 0);
  const auto json = nlohmann::json::parse(formatPointFolderJson(report));
  EXPECT_EQ(json["yaw_source"], "test poses");
  EXPECT_EQ(json["methods"][0]["bands"][1]["min_abs_yaw"], 30.0);
  EXPECT_EQ(json["methods"][0]["bands"][0]["fitted"], 1);
  const std::string text = formatPointFolderText(report);
  EXPECT_NE(text.find("1 faces in no band"), std::string::npos) << text;
  EXPECT_NE(text.find("|yaw| 30-60  fits  faces 1  fitted 0"), std::string::npos) << text;
  EXPECT_NE(formatPointFolderCsv(report).find("b,fits,rejected,"), std::string::npos);
}

TEST(YawBands, PoseCsvErrorsNameTheFile) {
  test::TempDir dir;
  const auto message = [&](const std::string& text) {
    const fs::path file = dir / "poses.csv";
    test::writeFile(file, text);
    try {
      readPoseCsv(file);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("image,yaw\na.jpg,3\n").find("no column 'yaw_deg'"), std::string::npos);
  EXPECT_NE(message("image,yaw_deg\na.jpg,left\n").find("line 2: yaw_deg 'left'"),
            std::string::npos);
  EXPECT_NE(message("image,yaw_deg\na.jpg,3\nx/a.png,4\n").find("'a' is listed twice"),
            std::string::npos);
  EXPECT_NE(message("image,yaw_deg\na.jpg,3\n").find("no error"), std::string::npos);
  EXPECT_THROW(readPoseCsv(dir / "none.csv"), InputError);
}

}  // namespace
}  // namespace clm3d
