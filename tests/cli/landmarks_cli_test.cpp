// clm3d landmarks convert / info through the real binary: exit codes 0 (done), 1 (bad input, one
// message naming the file) and 2 (bad usage), and the converted files.
#include <gtest/gtest.h>

#include "core/scheme/landmark_file.hpp"
#include "core/scheme/pts_format.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::runClm3d;

// A 68-point iBUG .pts whose point k is at 1-based (k + 1, 2k + 1), with iBUG 30 missing.
std::filesystem::path writeIbugPts(const test::TempDir& dir) {
  LandmarkSet set(68, 2);
  for (int k = 0; k < 68; ++k) {
    if (k != 30) set.set(k, Eigen::Vector2d(k, 2.0 * k));
  }
  const auto path = dir / "face68.pts";
  test::writeFile(path, formatPts(set));
  return path;
}

TEST(LandmarksCli, ConvertsIbug68PtsToThesis25Csv) {
  test::TempDir dir;
  const auto in = writeIbugPts(dir);
  const auto out = dir / "face25.csv";
  const auto result = runClm3d("landmarks convert --in " + in.string() + " --out " + out.string() +
                               " --to thesis25");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("25 points (22 present"), std::string::npos) << result.output;
  const auto points = readLandmarks(out, &Scheme::thesis25());
  EXPECT_EQ(points.presentCount(), 22);  // no earlobes, no nose tip
  EXPECT_FALSE(points.has(11));
  EXPECT_EQ(points.point(1), Eigen::Vector3d(45, 90, 0));  // left eye outer = iBUG 45
  EXPECT_NE(test::readFile(out).find("left_eye_outer,45,90"), std::string::npos);
}

TEST(LandmarksCli, ConvertsFormatOnlyByDefault) {
  test::TempDir dir;
  const auto in = writeIbugPts(dir);
  const auto out = dir / "face68.ljson";
  const auto result = runClm3d("landmarks convert --in " + in.string() + " --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto back = readLandmarks(out, &Scheme::ibug68());
  EXPECT_EQ(back, readLandmarks(in, &Scheme::ibug68()));
  EXPECT_NE(test::readFile(out).find("\"ibug68\""), std::string::npos);
}

TEST(LandmarksCli, InfoListsMissingPointsByName) {
  test::TempDir dir;
  const auto in = writeIbugPts(dir);
  const auto out = dir / "face25.pts";
  ASSERT_EQ(runClm3d("landmarks convert --in " + in.string() + " --out " + out.string() +
                     " --from ibug68 --to thesis25")
                .exitCode,
            0);
  const auto result = runClm3d("landmarks info " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("points: 25"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("dimensions: 2"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("scheme: thesis25"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("missing: 3"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("left_earlobe"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("nose_tip"), std::string::npos) << result.output;
}

TEST(LandmarksCli, ConvertsToALabSchemeById) {
  test::TempDir dir;
  test::writeFile(dir / "lab.json", R"({"name": "lab3", "landmarks": [{"id": "nose_tip"},
      {"id": "left_eye_outer"}, {"id": "forehead"}], "normalisation": [0, 1]})");
  const auto in = writeIbugPts(dir);
  const auto mid = dir / "face25.ljson";
  ASSERT_EQ(runClm3d("landmarks convert --in " + in.string() + " --out " + mid.string() +
                     " --to thesis25")
                .exitCode,
            0);
  const auto out = dir / "lab.csv";
  const auto result = runClm3d("landmarks convert --in " + mid.string() + " --out " + out.string() +
                               " --to " + (dir / "lab.json").string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_EQ(test::readFile(out), "id,x,y\nnose_tip,,\nleft_eye_outer,45,90\nforehead,,\n");
}

TEST(LandmarksCli, BadInputExitsOneNamingTheFile) {
  test::TempDir dir;
  const auto bad = dir / "broken.pts";
  test::writeFile(bad, "version: 1\nn_points: 3\n{\n1 2\n}\n");
  auto result = runClm3d("landmarks info " + bad.string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("broken.pts:5: n_points says 3 but 1 points follow"),
            std::string::npos)
      << result.output;

  const auto in = writeIbugPts(dir);
  result = runClm3d("landmarks convert --in " + in.string() + " --out " + (dir / "x.txt").string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("x.txt: unknown landmark file extension"), std::string::npos)
      << result.output;

  result = runClm3d("landmarks convert --in " + in.string() + " --out " + (dir / "y.pts").string() +
                    " --from thesis26");
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("thesis26"), std::string::npos) << result.output;

  result = runClm3d("landmarks info " + (dir / "absent.ljson").string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("absent.ljson: file not found"), std::string::npos);
}

TEST(LandmarksCli, UsageErrorsExitTwo) {
  EXPECT_EQ(runClm3d("landmarks convert --out x.pts").exitCode, 2);
  EXPECT_EQ(runClm3d("landmarks").exitCode, 2);
  EXPECT_EQ(runClm3d("landmarks info").exitCode, 2);
  EXPECT_EQ(runClm3d("landmarks frobnicate").exitCode, 2);
}

}  // namespace
}  // namespace clm3d
