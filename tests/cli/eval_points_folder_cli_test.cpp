// clm3d eval-points over folders through the real binary: 68-point and 25-point truths paired by
// stem with two methods' predictions (.pts and .ljson), one prediction missing (a failure), the
// per-method figures, the per-image CSV and the JSON report; and the usage and input errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/detect/initialisation.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"
#include "core/model/model_file.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using test::runClm3d;

// The thesis25 points of a 68-point mark-up whose eye centres are 40 pixels apart, moved by dx.
LandmarkSet shifted(const LandmarkSet& points, double dx) {
  LandmarkSet moved = points;
  for (int i = 0; i < points.size(); ++i) {
    if (points.has(i))
      moved.set(i, Eigen::Vector2d(points.point(i).head<2>() + Eigen::Vector2d(dx, 0)));
  }
  return moved;
}

struct FolderFiles {
  test::TempDir dir;
  fs::path truth, methodA, methodB;
  FolderFiles() {
    truth = dir / "truth";
    methodA = dir / "fits-a";
    methodB = dir / "fits-b";
    for (const fs::path& folder : {truth, methodA, methodB}) fs::create_directories(folder);
    LandmarkSet ibug(68, 2);
    for (int i = 0; i < 68; ++i) ibug.set(i, Eigen::Vector2d(30.0 + 2.0 * i, 90.0 + (i % 5)));
    for (int i = 36; i < 42; ++i) ibug.set(i, Eigen::Vector2d(80.0, 50.0 + (i - 36)));
    for (int i = 42; i < 48; ++i) ibug.set(i, Eigen::Vector2d(120.0, 50.0 + (i - 42)));
    // Three images: two 68-point truths and one 25-point truth (23 comparable points each).
    writeLandmarks(truth / "img1.pts", ibug, Scheme::ibug68());
    writeLandmarks(truth / "img2.pts", ibug, Scheme::ibug68());
    const LandmarkSet thesis = readLandmarks(truth / "img1.pts", &Scheme::thesis25());
    writeLandmarks(truth / "img3.pts", thesis, Scheme::thesis25());
    test::writeFile(truth / "img1.jpg", "an image beside its truth is ignored\n");
    // Method A: img1 off by 0.1 eye distances, img2 by 0.2, img3 missing.
    writeLandmarks(methodA / "img1.pts", shifted(thesis, 4.0), Scheme::thesis25());
    writeLandmarks(methodA / "img2.pts", shifted(thesis, 8.0), Scheme::thesis25());
    test::writeFile(methodA / "summary.csv", "not a prediction\n");
    // Method B: every image off by 0.05, as LJSON.
    for (const char* stem : {"img1", "img2", "img3"}) {
      writeLandmarks(methodB / (std::string(stem) + ".ljson"), shifted(thesis, 2.0),
                     Scheme::thesis25());
    }
  }
};

TEST(EvalPointsFolderCli, PairsByStemCountsMissingPredictionsAndWritesTheTable) {
  const FolderFiles f;
  const fs::path csv = f.dir / "per-image.csv";
  const fs::path report = f.dir / "report.json";
  const auto result = runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " +
                               f.methodA.string() + " --pred-dir " + f.methodB.string() +
                               " --csv " + csv.string() + " --out " + report.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "(3 images, scheme thesis25, all points)"))
      << result.output;
  EXPECT_TRUE(test::contains(
      result.output, "fits-a (" + f.methodA.string() +
                         "): mean error 0.1500, median 0.1500 over 2/3 images; within 0.18: "
                         "23/69 points (33.3%); missing predictions: 1"))
      << result.output;
  EXPECT_TRUE(
      test::contains(result.output, "fits-b (" + f.methodB.string() +
                                        "): mean error 0.0500, median 0.0500 over 3/3 images; "
                                        "within 0.18: 69/69 points (100.0%); missing "
                                        "predictions: 0"))
      << result.output;

  const std::string table = test::readFile(csv);
  std::istringstream in(table);
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);) rows.push_back(line);
  ASSERT_EQ(rows.size(), 7U) << table;
  EXPECT_EQ(rows[0],
            "image,method,status,error,max_error,true_points,scored_points,found_points,"
            "inter_ocular,box_error,box_size,yaw_deg,prediction");
  EXPECT_TRUE(test::contains(rows[1], "img1,fits-a,ok,0.100000,0.100000,23,23,23,40.000,"))
      << rows[1];
  EXPECT_TRUE(test::contains(rows[3], "img2,fits-a,ok,0.200000,0.200000,23,23,0,40.000,"))
      << rows[3];
  EXPECT_EQ(rows[5], "img3,fits-a,missing,,,23,,,,,,,");
  EXPECT_TRUE(test::contains(rows[6], "img3,fits-b,ok,0.050000,")) << rows[6];
  EXPECT_TRUE(test::contains(rows[6], "img3.ljson")) << rows[6];

  const auto json = nlohmann::json::parse(test::readFile(report));
  EXPECT_EQ(json["format"], "clm3d-point-folder-evaluation");
  EXPECT_EQ(json["images"], 3);
  EXPECT_EQ(json["methods"][0]["missing"], 1);
  EXPECT_NEAR(json["methods"][0]["median_error"].get<double>(), 0.15, 1e-9);
  EXPECT_NEAR(json["methods"][1]["found_share"].get<double>(), 1.0, 1e-12);
}

TEST(EvalPointsFolderCli, YawBandsFromAPosesCsv) {
  const FolderFiles f;
  const fs::path poses = f.dir / "index.csv";
  test::writeFile(poses,
                  "image,yaw_deg,visible_count,split\nimages/img1.jpg,-20,21,test\n"
                  "images/img2.jpg,50,15,test\nimages/img3.jpg,80,12,test\n");
  const auto text =
      runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " + f.methodA.string() +
               " --poses " + poses.string() + " --yaw-bands 0,45,90");
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_TRUE(test::contains(text.output, "|yaw| 0-45  fits-a  faces 1  fitted 1")) << text.output;
  EXPECT_TRUE(test::contains(text.output, "|yaw| 45-90  fits-a  faces 2  fitted 1")) << text.output;
  const auto json = nlohmann::json::parse(runClm3d("eval-points --truth-dir " + f.truth.string() +
                                                   " --pred-dir " + f.methodA.string() +
                                                   " --poses " + poses.string() + " --json")
                                              .output);
  ASSERT_EQ(json["methods"][0]["bands"].size(), 3U);
  EXPECT_EQ(json["methods"][0]["bands"][2]["faces"], 1);  // img3, 80 degrees: no prediction
  EXPECT_EQ(json["methods"][0]["bands"][2]["fitted"], 0);
  EXPECT_NEAR(json["methods"][0]["bands"][1]["mean_error"].get<double>(), 0.2, 1e-9);
  const auto none =
      runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " + f.methodA.string());
  EXPECT_TRUE(test::contains(none.output, "yaw bands: skipped")) << none.output;

  // Off the face: a fitted face whose error over its box exceeds --off-face-above. img1 (0.1 eye
  // distances) and img2 (0.2) share their box, so a line between their box errors counts img2
  // (band 45-90) and not img1 (band 0-45).
  const fs::path csv = f.dir / "rows.csv";
  ASSERT_EQ(runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " +
                     f.methodA.string() + " --csv " + csv.string())
                .exitCode,
            0);
  std::map<std::string, double> boxError;
  std::istringstream rows(test::readFile(csv));
  for (std::string line; std::getline(rows, line);) {
    std::vector<std::string> cells;
    std::istringstream cellStream(line);
    for (std::string cell; std::getline(cellStream, cell, ',');) cells.push_back(cell);
    if (cells.size() > 9 && cells[2] == "ok") boxError[cells[0]] = std::stod(cells[9]);
  }
  ASSERT_EQ(boxError.size(), 2U);
  ASSERT_LT(boxError["img1"], boxError["img2"]);
  const double line = 0.5 * (boxError["img1"] + boxError["img2"]);
  const auto off = runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " +
                            f.methodA.string() + " --poses " + poses.string() +
                            " --yaw-bands 0,45,90 --off-face-above " + std::to_string(line));
  ASSERT_EQ(off.exitCode, 0) << off.output;
  EXPECT_TRUE(test::contains(off.output, "|yaw| 0-45  fits-a  faces 1  fitted 1")) << off.output;
  const auto at = [&](const std::string& band) {
    const auto start = off.output.find("|yaw| " + band + "  fits-a");
    return off.output.substr(start, off.output.find('\n', start) - start);
  };
  EXPECT_TRUE(test::contains(at("0-45"), "): 0")) << off.output;
  EXPECT_TRUE(test::contains(at("45-90"), "): 1")) << off.output;
  EXPECT_EQ(json["methods"][0]["bands"][1]["off_face"], boxError["img2"] > 0.08 ? 1 : 0);
  const auto bad =
      runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " + f.methodA.string() +
               " --poses " + poses.string() + " --yaw-bands 60,30");
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_TRUE(test::contains(bad.output, "yaw band edges '60,30'")) << bad.output;
}

// The yaw of each truth from the model fitted to its points: three truths projected from the
// fixture model at known yaws land in their bands; the band table says where the yaws came from.
TEST(EvalPointsFolderCli, YawBandsFromTheModelFittedToTheTruths) {
  test::TempDir dir;
  const ClmModel& model = test::fitTestModel();
  const fs::path modelFile = dir / "model.clm3d";
  saveModel(model, modelFile);
  const fs::path truth = dir / "truth";
  fs::create_directories(truth);
  const Camera camera = Camera::fromVerticalFov(640, 480, kDefaultVerticalFovDeg);
  const std::vector<std::pair<std::string, double>> faces{
      {"front", 5.0}, {"half", 45.0}, {"side", -70.0}};
  for (const auto& [stem, yaw] : faces) {
    FitState state;
    state.pose = Pose::fromDegrees(5.0, yaw, 0.0, {0.0, 0.0, -450.0}, 1.0);
    state.shape = Eigen::VectorXd::Zero(model.shape.modeCount());
    const Eigen::Matrix2Xd points = projectState(model, camera, state);
    LandmarkSet set(25, 2);
    for (int i = 0; i < 25; ++i) set.set(i, Eigen::Vector2d(points.col(i)));
    writeLandmarks(truth / (stem + ".pts"), set, Scheme::thesis25());
  }
  const auto result = runClm3d("eval-points --truth-dir " + truth.string() + " --pred-dir " +
                               truth.string() + " --model " + modelFile.string() + " --json");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output);
  const auto& bands = json["methods"][0]["bands"];
  ASSERT_EQ(bands.size(), 3U);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(bands[k]["faces"], 1) << "band " << k << ": " << bands.dump();
    EXPECT_EQ(bands[k]["fitted"], 1) << "band " << k;
  }
  EXPECT_TRUE(test::contains(json["yaw_source"].get<std::string>(), "fitted to the truth"));
}

TEST(EvalPointsFolderCli, ChosenPointsAndLabels) {
  const FolderFiles f;
  const auto result = runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " +
                               f.methodB.string() + " --label mine --points 8,11 --json");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output);
  EXPECT_EQ(json["methods"][0]["label"], "mine");
  EXPECT_EQ(json["methods"][0]["true_points"], 6);
  EXPECT_EQ(json["points"], nlohmann::json::array({8, 11}));
}

TEST(EvalPointsFolderCli, SameFacesScoresOnlyTheImagesEveryMethodFitted) {
  const FolderFiles f;
  // Method A has no img3; method B's summary marks img2 rejected: only img1 is left to both.
  test::writeFile(f.methodB / "summary.csv",
                  "image,status\n/x/img1.jpg,ok\n/x/img2.jpg,rejected\n");
  const auto result =
      runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " + f.methodA.string() +
               " --pred-dir " + f.methodB.string() + " --same-faces");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "(1 images, scheme thesis25, all points)"))
      << result.output;
  EXPECT_TRUE(test::contains(result.output,
                             "same faces: the 1 images every method fitted (2 that one or more "
                             "did not fit left out)"))
      << result.output;
  // img1 alone: A off by 0.1, B by 0.05; neither has a missing prediction any more.
  EXPECT_TRUE(test::contains(result.output, "mean error 0.1000, median 0.1000 over 1/1 images"))
      << result.output;
  EXPECT_TRUE(test::contains(result.output, "mean error 0.0500, median 0.0500 over 1/1 images"))
      << result.output;
  const auto json = nlohmann::json::parse(
      runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " + f.methodA.string() +
               " --pred-dir " + f.methodB.string() + " --same-faces --json")
          .output);
  EXPECT_EQ(json["images"], 1);
  EXPECT_EQ(json["not_fitted_by_all"], 2);
  EXPECT_EQ(json["methods"][0]["missing"], 0);

  // No image fitted by all: an error naming the truth folder; with single files, a usage error.
  fs::remove(f.methodA / "img1.pts");
  const auto none =
      runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " + f.methodA.string() +
               " --pred-dir " + f.methodB.string() + " --same-faces");
  EXPECT_NE(none.exitCode, 0);
  EXPECT_TRUE(test::contains(none.output, f.truth.string())) << none.output;
  EXPECT_TRUE(test::contains(none.output, "no truth image that every prediction folder fitted"))
      << none.output;
  const auto files = runClm3d("eval-points --truth " + (f.truth / "img1.pts").string() +
                              " --pred " + (f.methodB / "img1.ljson").string() + " --same-faces");
  EXPECT_NE(files.exitCode, 0);
  EXPECT_TRUE(test::contains(files.output, "--same-faces")) << files.output;
}

// --roc over the fits' summary.csv confidences, and the counts at --accept-at: right fits are
// those within 0.15 (method A's img1 at 0.1, method B's three at 0.05), wrong A's img2 (0.2).
TEST(EvalPointsFolderCli, RocCountsTheFitsKeptAndAcceptedAtAThreshold) {
  const FolderFiles f;
  test::writeFile(f.methodA / "summary.csv",
                  "image,status,confidence\nimg1.jpg,ok,0.9\n"
                  "img2.jpg,ok,0.6\nimg3.jpg,no-face,\n");
  test::writeFile(f.methodB / "summary.csv",
                  "image,status,confidence\nimg1.jpg,ok,0.8\nimg2.jpg,ok,0.4\nimg3.jpg,ok,0.55\n");
  const std::string command = "eval-points --truth-dir " + f.truth.string() + " --pred-dir " +
                              f.methodA.string() + " --pred-dir " + f.methodB.string() + " --roc";
  const auto result = runClm3d(command);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "(4 right, 1 wrong: error > 0.150): AUC 0.500"))
      << result.output;
  EXPECT_TRUE(test::contains(result.output,
                             "at confidence >= 0.5: keeps 3 of 4 right fits, accepts 1 of 1 wrong "
                             "ones and 0 of 0 more than 0.3 off"))
      << result.output;
  const auto stricter = runClm3d(command + " --accept-at 0.85");
  ASSERT_EQ(stricter.exitCode, 0) << stricter.output;
  EXPECT_TRUE(test::contains(stricter.output,
                             "at confidence >= 0.85: keeps 1 of 4 right fits, accepts 0 of 1 "
                             "wrong ones"))
      << stricter.output;
}

TEST(EvalPointsFolderCli, BadInputNamesTheFileAndMixedModesAreUsageErrors) {
  const FolderFiles f;
  LandmarkSet ten(10, 2);
  for (int i = 0; i < 10; ++i) ten.set(i, Eigen::Vector2d(i, i));
  const fs::path bad = f.dir / "bad";
  fs::create_directories(bad);
  test::writeFile(
      bad / "img2.pts", "version: 1\nn_points: 10\n{\n" + [] {
        std::string points;
        for (int i = 0; i < 10; ++i) points += std::to_string(i + 1) + " 5\n";
        return points;
      }() + "}\n");
  const auto wrongCount =
      runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " + bad.string());
  EXPECT_EQ(wrongCount.exitCode, 1) << wrongCount.output;
  EXPECT_TRUE(test::contains(wrongCount.output, (bad / "img2.pts").string())) << wrongCount.output;
  EXPECT_TRUE(test::contains(wrongCount.output, "10 points")) << wrongCount.output;

  const fs::path absent = f.dir / "absent";
  const auto missing =
      runClm3d("eval-points --truth-dir " + f.truth.string() + " --pred-dir " + absent.string());
  EXPECT_EQ(missing.exitCode, 1) << missing.output;
  EXPECT_TRUE(test::contains(missing.output, absent.string())) << missing.output;

  const auto mixed = runClm3d("eval-points --truth " + (f.truth / "img1.pts").string() +
                              " --pred-dir " + f.methodA.string());
  EXPECT_EQ(mixed.exitCode, 2) << mixed.output;
  const auto both =
      runClm3d("eval-points --truth " + (f.truth / "img1.pts").string() + " --truth-dir " +
               f.truth.string() + " --pred-dir " + f.methodA.string());
  EXPECT_EQ(both.exitCode, 2) << both.output;
  const auto csvWithFiles =
      runClm3d("eval-points --truth " + (f.truth / "img1.pts").string() + " --pred " +
               (f.methodA / "img1.pts").string() + " --csv x.csv");
  EXPECT_EQ(csvWithFiles.exitCode, 2) << csvWithFiles.output;
  EXPECT_TRUE(test::contains(csvWithFiles.output, "--csv")) << csvWithFiles.output;
  // The single-file mode is unchanged.
  const auto single = runClm3d("eval-points --truth " + (f.truth / "img1.pts").string() +
                               " --pred " + (f.methodA / "img1.pts").string());
  ASSERT_EQ(single.exitCode, 0) << single.output;
  EXPECT_TRUE(test::contains(single.output, "error 0.1000 over 23/23 points")) << single.output;
}

TEST(EvalPointsFolderCli, LfpwTruthAgainstItselfScoresZero) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const fs::path truth = data / "photos" / "lfpw" / "test";
  if (!fs::is_directory(truth)) GTEST_SKIP() << truth << " not found";
  const auto result = runClm3d("eval-points --truth-dir " + truth.string() + " --pred-dir " +
                               truth.string() + " --label self --json");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output);
  EXPECT_EQ(json["images"], 224);
  EXPECT_EQ(json["methods"][0]["missing"], 0);
  EXPECT_NEAR(json["methods"][0]["mean_error"].get<double>(), 0.0, 1e-12);
}

}  // namespace
}  // namespace clm3d
