// clm3d eval-points and clm3d plot through the real binary: a fit scored against a 68-point
// mark-up over chosen points (text, JSON, report file), a chart drawn from a table, and bad input
// exiting 1 with a message naming the file or option.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::runClm3d;

struct PointFiles {
  test::TempDir dir;
  std::string truth, fit;
  PointFiles() {
    truth = (dir / "truth.pts").string();
    fit = (dir / "fit.pts").string();
    // A 68-point truth whose eye contours put the eye centres 40 pixels apart.
    LandmarkSet ibug(68, 2);
    for (int i = 0; i < 68; ++i) ibug.set(i, Eigen::Vector2d(30.0 + 2.0 * i, 90.0 + (i % 5)));
    for (int i = 36; i < 42; ++i) ibug.set(i, Eigen::Vector2d(80.0, 50.0 + (i - 36)));
    for (int i = 42; i < 48; ++i) ibug.set(i, Eigen::Vector2d(120.0, 50.0 + (i - 42)));
    writeLandmarks(truth, ibug, Scheme::ibug68());
    auto points = readLandmarks(truth, &Scheme::thesis25());
    // The fit: 4 pixels (0.1 eye distances) right everywhere, but the left cheek 40 pixels off.
    for (int i = 0; i < 25; ++i) {
      if (!points.has(i)) continue;
      const double dx = i == 19 ? 40.0 : 4.0;
      points.set(i, Eigen::Vector2d(points.point(i).head<2>() + Eigen::Vector2d(dx, 0.0)));
    }
    writeLandmarks(fit, points, Scheme::thesis25());
  }
};

TEST(EvalPointsCli, ScoresTheChosenPointsAgainstA68PointMarkUp) {
  PointFiles files;
  const auto some = runClm3d("eval-points --truth " + files.truth + " --pred " + files.fit +
                             " --points 1-18,22 --label detector");
  ASSERT_EQ(some.exitCode, 0) << some.output;
  EXPECT_NE(some.output.find("19 points: 1 2 3"), std::string::npos) << some.output;
  EXPECT_NE(some.output.find("detector (" + files.fit + "): error 0.1000 over 19/19 points"),
            std::string::npos)
      << some.output;
  EXPECT_NE(some.output.find("eye distance 40.0 px"), std::string::npos) << some.output;

  // All 23 comparable points: the cheek (1.0) now counts, (22 x 0.1 + 1.0) / 23.
  const auto report = files.dir / "report.json";
  const auto all = runClm3d("eval-points --truth " + files.truth + " --pred " + files.fit +
                            " --json --out " + report.string());
  ASSERT_EQ(all.exitCode, 0) << all.output;
  const auto json = nlohmann::json::parse(test::readFile(report));
  EXPECT_NEAR(json["predictions"][0]["error"].get<double>(), (22 * 0.1 + 1.0) / 23.0, 1e-9);
  EXPECT_EQ(json["predictions"][0]["scored_points"], 23);
  EXPECT_NEAR(json["predictions"][0]["max_error"].get<double>(), 1.0, 1e-9);
}

TEST(EvalPointsCli, BadInputExitsOneNamingTheProblem) {
  PointFiles files;
  const auto badList =
      runClm3d("eval-points --truth " + files.truth + " --pred " + files.fit + " --points 1-40");
  EXPECT_EQ(badList.exitCode, 1);
  EXPECT_NE(badList.output.find("--points: point '1-40' is not in 1-25"), std::string::npos)
      << badList.output;
  const auto missing = (files.dir / "absent.pts").string();
  const auto absent = runClm3d("eval-points --truth " + files.truth + " --pred " + missing);
  EXPECT_EQ(absent.exitCode, 1);
  EXPECT_NE(absent.output.find("absent.pts"), std::string::npos) << absent.output;
}

TEST(PlotCli, DrawsOneLinePerSeriesAndRejectsUnknownColumns) {
  test::TempDir dir;
  test::writeFile(dir / "results.csv",
                  "identities,test,augmentation,error\n1,james,on,0.3\n5,james,on,0.2\n"
                  "1,james,off,0.35\n5,james,off,0.3\n1,photos,on,0.5\n");
  const auto png = dir / "plot.png";
  const auto result =
      runClm3d("plot --csv " + (dir / "results.csv").string() + " --out " + png.string() +
               " --x identities --y error --series test --series augmentation "
               "--where test=james --log-x --title 'error against identities'");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("(2 series)"), std::string::npos) << result.output;
  ASSERT_TRUE(std::filesystem::exists(png));
  EXPECT_GT(std::filesystem::file_size(png), 5000u);

  const auto bad = runClm3d("plot --csv " + (dir / "results.csv").string() + " --out " +
                            png.string() + " --x identities --y mean_error");
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.output.find("results.csv:1: no column 'mean_error' (y)"), std::string::npos)
      << bad.output;
  const auto badWhere = runClm3d("plot --csv " + (dir / "results.csv").string() + " --out " +
                                 png.string() + " --x identities --y error --where test");
  EXPECT_EQ(badWhere.exitCode, 1);
  EXPECT_NE(badWhere.output.find("expected COLUMN=VALUE"), std::string::npos) << badWhere.output;
}

}  // namespace
}  // namespace clm3d
