// clm3d synth-head end to end: files written for each seed, landmarks readable back as the
// thesis's 25 points, the mesh loadable, and clear errors for bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/mesh/mesh_import.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

TEST(SynthHeadCli, WritesMeshTextureAndLandmarksPerSeed) {
  const test::TempDir dir;
  const auto result = test::runClm3d(
      "synth-head --seed 5 --count 2 --expression smile "
      "--texture-size 512 --out " +
      (dir / "heads").string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const char* seed : {"5", "6"}) {
    const fs::path stem = dir / ("heads/head-" + std::string(seed));
    for (const char* ext : {".obj", ".mtl", ".png", ".ljson"}) {
      EXPECT_TRUE(fs::exists(stem.string() + ext)) << stem.string() + ext;
    }
    const LandmarkSet points = readLandmarks(stem.string() + ".ljson", &Scheme::thesis25());
    ASSERT_EQ(points.size(), 25);
    EXPECT_EQ(points.presentCount(), 25);
    EXPECT_EQ(points.dims(), 3);
    EXPECT_NEAR(points.point(0).norm(), 0.0, 1e-6);  // landmark 1 at the origin
    const double iod = (points.point(7) - points.point(10)).norm();
    EXPECT_GT(iod, 54.0);
    EXPECT_LT(iod, 76.0);
  }
  EXPECT_FALSE(fs::exists(dir / "heads/head-7.obj"));
}

TEST(SynthHeadCli, WrittenMeshLoadsBackTextured) {
  const test::TempDir dir;
  const auto result = test::runClm3d("synth-head --seed 9 --texture-size 256 --face-step 2 --out " +
                                     dir.path().string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const TexturedMesh mesh = loadTexturedMesh(dir / "head-9.obj");
  EXPECT_NO_THROW(mesh.validate());
  EXPECT_EQ(mesh.texture.rows, 256);
  EXPECT_GT(mesh.triangleCount(), 10000U);
}

TEST(SynthHeadCli, UnknownExpressionListsTheValidNames) {
  const test::TempDir dir;
  const auto result =
      test::runClm3d("synth-head --seed 1 --expression grin --out " + dir.path().string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("grin"), std::string::npos) << result.output;
  for (const char* name : {"neutral", "smile", "surprise", "open-mouth", "frown"}) {
    EXPECT_NE(result.output.find(name), std::string::npos) << result.output;
  }
  EXPECT_FALSE(fs::exists(dir / "head-1.obj"));
}

TEST(SynthHeadCli, MissingOutIsAUsageError) {
  const auto result = test::runClm3d("synth-head --seed 1");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("--out"), std::string::npos) << result.output;
}

TEST(SynthHeadCli, ContactSheetShowsFifteenViewsPerHead) {
  const test::TempDir dir;
  const fs::path sheet = dir / "sheet.png";
  const auto result =
      test::runClm3d("synth-head --seed 2 --texture-size 256 --face-step 2 --tile-size 64 --out " +
                     dir.path().string() + " --contact-sheet " + sheet.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(fs::exists(sheet));
  EXPECT_NE(result.output.find("15 views"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace clm3d
