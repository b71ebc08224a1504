// `clm3d ict-texture` errors: usage mistakes exit 2, bad data exits 1 with a message naming the
// file; a run on the real model is in the registration unit tests (it needs ../shared/data).
#include <gtest/gtest.h>

#include "core/mesh/mesh_export.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/synth/synth_head.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::quoted;

using test::runClm3d;
using test::TempDir;

// A small procedural head saved as a scan with its landmarks.
struct Scan {
  std::filesystem::path mesh, landmarks;
};
Scan writeScan(const TempDir& dir) {
  SynthOptions options;
  options.faceStepDegrees = 3.0;
  options.textureSize = 256;
  const SynthHead head = generateHead(1, Expression{}, options);
  Scan scan{dir / "head.obj", dir / "head.ljson"};
  saveObj(head.mesh, scan.mesh);
  writeLandmarks(scan.landmarks, head.landmarks, Scheme::thesis25());
  return scan;
}

TEST(IctTextureCli, HelpNamesTheOptions) {
  const auto result = runClm3d("ict-texture --help");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const char* option : {"--model", "--vertices", "--scan", "--landmarks", "--out",
                             "--texture-size", "--samples", "--contact-sheet"}) {
    EXPECT_NE(result.output.find(option), std::string::npos) << option;
  }
}

// `clm3d ict-texture` on `model` and the given scan files, with the fixture's vertex table.
std::string command(const TempDir& dir, const std::filesystem::path& model,
                    const std::filesystem::path& mesh, const std::filesystem::path& landmarks) {
  return "ict-texture --model " + quoted(model) + " --vertices " +
         quoted(test::fixturePath("ict-facekit/thesis25_vertices.json")) + " --scan " +
         quoted(mesh) + " --landmarks " + quoted(landmarks) + " --out " + quoted(dir / "out");
}

TEST(IctTextureCli, UsageErrorsExitTwo) {
  TempDir dir;
  const Scan scan = writeScan(dir);
  const std::string base = command(dir, dir.path(), scan.mesh, scan.landmarks);
  EXPECT_EQ(runClm3d("ict-texture --scan " + quoted(scan.mesh)).exitCode, 2);  // missing options
  EXPECT_EQ(runClm3d(base + " --texture-size 10").exitCode, 2);
  const auto up = runClm3d(base + " --up sideways");
  EXPECT_EQ(up.exitCode, 2);
  EXPECT_NE(up.output.find("--up"), std::string::npos) << up.output;
  EXPECT_EQ(runClm3d(base + " --up +y --front +y").exitCode, 2);
  EXPECT_EQ(runClm3d(command(dir, dir / "none.tar.xz", scan.mesh, scan.landmarks)).exitCode, 2);
}

TEST(IctTextureCli, BadDataExitsOneNamingTheFile) {
  TempDir dir;
  const Scan scan = writeScan(dir);
  // Not an archive.
  test::writeFile(dir / "model.tar.xz", "not an archive");
  const auto notArchive = runClm3d(command(dir, dir / "model.tar.xz", scan.mesh, scan.landmarks));
  EXPECT_EQ(notArchive.exitCode, 1) << notArchive.output;
  EXPECT_NE(notArchive.output.find("model.tar.xz"), std::string::npos) << notArchive.output;
  // A folder without the neutral mesh.
  std::filesystem::create_directories(dir / "empty-model");
  const auto noNeutral = runClm3d(command(dir, dir / "empty-model", scan.mesh, scan.landmarks));
  EXPECT_EQ(noNeutral.exitCode, 1) << noNeutral.output;
  EXPECT_NE(noNeutral.output.find("generic_neutral_mesh"), std::string::npos) << noNeutral.output;
  // Landmarks of another scheme size.
  test::writeFile(dir / "two.pts", "version: 1\nn_points: 2\n{\n1 2\n3 4\n}\n");
  const auto badLandmarks = runClm3d(command(dir, dir / "empty-model", scan.mesh, dir / "two.pts"));
  EXPECT_EQ(badLandmarks.exitCode, 1) << badLandmarks.output;
  EXPECT_NE(badLandmarks.output.find("two.pts"), std::string::npos) << badLandmarks.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "ict-head.obj"));
}

}  // namespace
}  // namespace clm3d
