// AFLW 21-point truth scored against thesis25 and 68-point (dlib) predictions on the points the
// schemes share, as ../shared/tools/score_aflw21.py pairs them: a hand-made fixture of three
// faces (one frontal, one turned with six points marked invisible including an eye centre, one
// never fitted), checked point by point against figures worked out by hand.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "core/common/error.hpp"
#include "core/eval/detail/scored_truth.hpp"
#include "core/eval/point_folder_error.hpp"
#include "core/eval/yaw_bands.hpp"
#include "core/scheme/landmark_file.hpp"
#include "tests/support/test_files.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

// The 21 AFLW points of the frontal face (0-based pixels, "left" = the image's left). The brow
// centres (2, 5) and the mouth centre (19) have no thesis25 counterpart; brow centre 2 is the
// highest point, so the box of every marked point (x 5..75, y 5..80) is taller than that of the
// paired ones (y 20..80).
constexpr std::array<std::array<double, 2>, 21> kAflw = {
    {{10, 20}, {20, 5},  {30, 20}, {50, 20}, {60, 15}, {70, 20}, {15, 30},
     {22, 30}, {29, 30}, {51, 30}, {58, 30}, {65, 30}, {5, 45},  {33, 50},
     {40, 45}, {47, 50}, {75, 45}, {28, 65}, {40, 70}, {52, 65}, {40, 80}}};

// AFLW points (1-based) hidden on the turned face: the image-left brow corners, eye and ear lobe.
bool hiddenWhenTurned(int aflw) {
  return aflw == 1 || aflw == 3 || aflw == 7 || aflw == 8 || aflw == 9 || aflw == 13;
}

// A 21-point .pts (1-based on disk), invisible points written "-1 -1".
std::string aflwPts(bool turned) {
  std::ostringstream out;
  out << "version: 1\nn_points: 21\n{\n";
  for (int i = 0; i < 21; ++i) {
    if (turned && hiddenWhenTurned(i + 1)) {
      out << "-1 -1\n";
    } else {
      out << kAflw[static_cast<std::size_t>(i)][0] + 1 << ' '
          << kAflw[static_cast<std::size_t>(i)][1] + 1 << '\n';
    }
  }
  out << "}\n";
  return out.str();
}

// thesis25 id -> the AFLW point (1-based) it is marked as, written out here independently of the
// production table.
const std::map<std::string, int>& thesisFromAflw() {
  static const std::map<std::string, int> table = {
      {"right_brow_outer", 1},    {"right_brow_inner", 3},   {"left_brow_inner", 4},
      {"left_brow_outer", 6},     {"right_eye_outer", 7},    {"right_eye_centre", 8},
      {"right_eye_inner", 9},     {"left_eye_inner", 10},    {"left_eye_centre", 11},
      {"left_eye_outer", 12},     {"right_earlobe", 13},     {"right_nose_base", 14},
      {"nose_tip", 15},           {"left_nose_base", 16},    {"left_earlobe", 17},
      {"right_mouth_corner", 18}, {"left_mouth_corner", 20}, {"chin_centre", 21}};
  return table;
}

Eigen::Vector2d aflwPoint(int aflw) {
  const auto& p = kAflw[static_cast<std::size_t>(aflw - 1)];
  return {p[0], p[1]};
}

// A thesis25 prediction: each paired point at its AFLW position moved by `shift`, the nose tip
// further by noseDx; the unpaired points far off (never scored: the truth lacks them).
LandmarkSet thesisPrediction(const Eigen::Vector2d& shift, double noseDx) {
  const Scheme& scheme = Scheme::thesis25();
  LandmarkSet set(25, 2);
  for (int i = 0; i < 25; ++i) set.set(i, Eigen::Vector2d(500.0, 500.0));
  for (const auto& [id, aflw] : thesisFromAflw()) {
    set.set(scheme.indexOf(id), Eigen::Vector2d(aflwPoint(aflw) + shift));
  }
  const int nose = scheme.indexOf("nose_tip");
  set.set(nose, Eigen::Vector2d(set.point(nose).head<2>() + Eigen::Vector2d(noseDx, 0.0)));
  return set;
}

// A 68-point (iBUG, dlib) prediction that converts to the paired points moved by `shift`: single
// points placed directly, the other four points of each eye contour placed so that the contour's
// mean is the eye centre. The jaw, apart from the chin (8), is left at the face's middle.
LandmarkSet ibugPrediction(const Eigen::Vector2d& shift) {
  LandmarkSet set(68, 2);
  for (int i = 0; i < 68; ++i) set.set(i, Eigen::Vector2d(40.0, 50.0));
  const auto at = [&](int aflw) { return Eigen::Vector2d(aflwPoint(aflw) + shift); };
  const std::map<int, int> single = {{45, 12}, {36, 7},  {26, 6},  {22, 4},  {21, 3},
                                     {17, 1},  {42, 10}, {39, 9},  {30, 15}, {35, 16},
                                     {31, 14}, {54, 20}, {48, 18}, {8, 21}};
  for (const auto& [ibug, aflw] : single) set.set(ibug, at(aflw));
  const Eigen::Vector2d left = (6.0 * at(11) - at(10) - at(12)) / 4.0;  // iBUG 42-47
  for (const int i : {43, 44, 46, 47}) set.set(i, left);
  const Eigen::Vector2d right = (6.0 * at(8) - at(7) - at(9)) / 4.0;  // iBUG 36-41
  for (const int i : {37, 38, 40, 41}) set.set(i, right);
  return set;
}

TEST(AflwPairing, ReadsAflwTruthWithTheBoxOfEveryMarkedPoint) {
  test::TempDir dir;
  test::writeFile(dir / "a.pts", aflwPts(false));
  const ScoredTruth truth = readScoredTruth(dir / "a.pts", Scheme::thesis25());
  EXPECT_EQ(truth.fileScheme, "aflw21");
  EXPECT_EQ(truth.points.size(), 25);
  EXPECT_EQ(truth.points.presentCount(), 18);
  EXPECT_NEAR(truth.boxSize, std::sqrt(70.0 * 75.0), 1e-9);
  for (const auto& [id, aflw] : thesisFromAflw()) {
    const int i = Scheme::thesis25().indexOf(id);
    ASSERT_TRUE(truth.points.has(i)) << id;
    EXPECT_TRUE(truth.points.point(i).head<2>().isApprox(aflwPoint(aflw))) << id;
  }
  test::writeFile(dir / "b.pts", aflwPts(true));
  const ScoredTruth turned = readScoredTruth(dir / "b.pts", Scheme::thesis25());
  EXPECT_EQ(turned.points.presentCount(), 12);  // 18 paired, 6 invisible
  EXPECT_FALSE(turned.points.has(Scheme::thesis25().indexOf("right_eye_centre")));
  EXPECT_NEAR(turned.boxSize, std::sqrt(55.0 * 75.0), 1e-9);  // x 20..75: brow centre 2 is left
  EXPECT_THROW(readScoredTruth(dir / "a.pts", Scheme::ibug68()), InputError);
}

TEST(AflwPairing, ScoresThesisAndIbugPredictionsOnTheSharedVisiblePointsPerBand) {
  test::TempDir dir;
  const fs::path truth = dir / "truth";
  const fs::path fits = dir / "clm3d";
  const fs::path dlib = dir / "dlib";
  for (const fs::path& folder : {truth, fits, dlib}) fs::create_directories(folder);
  test::writeFile(truth / "a.pts", aflwPts(false));
  test::writeFile(truth / "b.pts", aflwPts(true));
  test::writeFile(truth / "c.pts", aflwPts(false));
  const Eigen::Vector2d shift(3.0, 4.0);  // 5 pixels
  writeLandmarks(fits / "a.pts", thesisPrediction(Eigen::Vector2d::Zero(), 9.0),
                 Scheme::thesis25());
  writeLandmarks(fits / "b.pts", thesisPrediction(shift, 0.0), Scheme::thesis25());
  writeLandmarks(dlib / "b.pts", ibugPrediction(shift), Scheme::ibug68());
  test::writeFile(dir / "index.csv",
                  "image,yaw_deg,visible_count,split\nimages/a.jpg,10,21,test\n"
                  "images/b.jpg,-70,15,test\nimages/c.jpg,40,21,test\n");

  auto report = evaluatePointFolders(truth, {fits, dlib}, {}, Scheme::thesis25(), {});
  EXPECT_EQ(report.truePoints, (std::vector<int>{18, 0, 18}));  // b has no right eye centre
  EXPECT_EQ(report.eyeNormalised, (std::vector<bool>{true, false, true}));
  const auto& a = *report.methods[0].results[0];
  EXPECT_EQ(a.scoredPoints, 18);
  EXPECT_NEAR(a.interOcular, 36.0, 1e-9);
  EXPECT_NEAR(a.error, 0.5 / 36.0, 1e-12);  // 9 pixels over 18 points
  EXPECT_NEAR(a.boxError, 0.5 / std::sqrt(70.0 * 75.0), 1e-12);
  const auto& b = *report.methods[0].results[1];
  EXPECT_EQ(b.scoredPoints, 12);
  EXPECT_TRUE(std::isnan(b.error));
  EXPECT_NEAR(b.boxError, 5.0 / std::sqrt(55.0 * 75.0), 1e-12);
  const auto& bDlib = *report.methods[1].results[1];
  EXPECT_EQ(bDlib.scoredPoints, 11);  // a 68-point prediction has no ear lobe
  EXPECT_NEAR(bDlib.boxError, 5.0 / std::sqrt(55.0 * 75.0), 1e-9);
  EXPECT_FALSE(report.methods[1].results[0].has_value());

  addYawBands(report, yawsByStem(report, readPoseCsv(dir / "index.csv")), {0.0, 30.0, 60.0, 90.0},
              "index.csv");
  const auto& clm3d = report.methods[0].bands;
  const auto& peer = report.methods[1].bands;
  EXPECT_EQ(clm3d[0].fitted, 1);
  EXPECT_NEAR(clm3d[0].meanBoxError, 0.5 / std::sqrt(5250.0), 1e-12);
  EXPECT_EQ(peer[0].fitted, 0);
  EXPECT_EQ(clm3d[1].faces, 1);
  EXPECT_EQ(clm3d[1].fitted, 0);
  EXPECT_EQ(peer[2].fitted, 1);
  EXPECT_NEAR(peer[2].meanBoxError, 5.0 / std::sqrt(4125.0), 1e-9);
  EXPECT_TRUE(std::isnan(peer[2].meanEyeError));
  const std::string table = formatYawBandMarkdown(report);
  EXPECT_NE(table.find("| 0-30 | 1 | 1 (100.0%) | 0.0069 | 0 (0.0%) | n/a |"), std::string::npos)
      << table;
  EXPECT_NE(table.find("clm3d fitted | clm3d error / box | dlib fitted"), std::string::npos)
      << table;
  const std::string text = formatPointFolderText(report);
  EXPECT_NE(text.find("aflw21 (3)"), std::string::npos) << text;
  EXPECT_NE(text.find("1 truths without both eye centres"), std::string::npos) << text;
}

}  // namespace
}  // namespace clm3d
