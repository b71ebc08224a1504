// clm3d demo end to end at a small size: heads, renders, training, the held-out test sequence,
// tracking with the overlay, and the evaluation whose summary ends the output; the output folder is
// a clm3d project (with a dataset manifest of the heads) that the studio opens.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/dataset/manifest.hpp"
#include "core/project/project.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

TEST(DemoCli, RunsTheWholeChainAndEndsWithTheErrorSummary) {
  test::TempDir dir;
  const auto result = test::runClm3d(
      "demo --heads 2 --samples 1 --size 64 --sequence-step 15 --out " + (dir / "demo").string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  // The project layout of core/project: models/, tracks/<video>-<model>.csv.
  for (const char* file :
       {"models/demo.clm3d", "tracks/sequence-demo.csv", "overlay.mp4", "sequence/truth.csv",
        "eval/report.json", "eval/cdf.png", "training-views.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "demo" / file)) << file;
  }
  // The track's quality, from the evaluation the demo wrote. Measured (seeded, the same every
  // run): 17 of 17 frames tracked, 16 converged, mean error 0.0910, 365 of 425 points (85.9%)
  // within 0.18. A track 10% worse fails the mean's bound.
  const nlohmann::json report =
      nlohmann::json::parse(test::readFile(dir / "demo" / "eval" / "report.json"));
  ASSERT_EQ(report.at("predictions").size(), 1u);
  const nlohmann::json& track = report.at("predictions").at(0);
  EXPECT_EQ(track.at("frames").at("truth"), 17);
  EXPECT_GE(track.at("frames").at("succeeded").get<int>(), 16);
  EXPECT_GE(track.at("frames").at("converged").get<int>(), 15);
  EXPECT_LT(track.at("error").at("mean").get<double>(), 0.100);
  EXPECT_GT(track.at("points").at("share_within_threshold").get<double>(), 0.82);
  const auto summary = result.output.find("error: mean");
  ASSERT_NE(summary, std::string::npos) << result.output;
  EXPECT_NE(result.output.find("overlay video:", summary), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("clm3d-studio --demo " + (dir / "demo").string()), std::string::npos)
      << result.output;

  const Project project = loadProject(dir / "demo");
  EXPECT_TRUE(std::filesystem::equivalent(project.folder, dir / "demo"));
  EXPECT_EQ(project.manifest, project.folder / "dataset.json");
  ASSERT_EQ(project.models.size(), 1u);
  EXPECT_EQ(project.models[0], project.folder / "models" / "demo.clm3d");
  ASSERT_EQ(project.videos.size(), 1u);
  ASSERT_EQ(project.tracks.size(), 1u);
  EXPECT_EQ(project.tracks[0], project.folder / "tracks" / "sequence-demo.csv");
  ASSERT_EQ(project.groundTruth.size(), 1u);
  EXPECT_EQ(project.groundTruth[0], project.folder / "sequence" / "truth.csv");
  for (const auto& file : {project.manifest, project.models[0], project.videos[0],
                           project.tracks[0], project.groundTruth[0]}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(file)) << file;
  }
  // The manifest lists the two training heads as scans and passes the loader's checks.
  const DatasetManifest manifest = loadManifest(project.manifest);
  ASSERT_EQ(manifest.scans.size(), 2u);
  EXPECT_TRUE(std::filesystem::equivalent(manifest.scans[0].mesh, dir / "demo/heads/head-1.obj"));
  EXPECT_TRUE(
      std::filesystem::equivalent(manifest.scans[1].landmarks, dir / "demo/heads/head-2.ljson"));
  EXPECT_EQ(manifest.scans[0].subject, "head-1");
  EXPECT_EQ(manifest.scheme, "thesis25");
}

TEST(DemoCli, RealWithoutTheSharedDataFailsAtOnceNamingWhatIsMissing) {
  test::TempDir dir;
  std::filesystem::create_directories(dir / "empty-data");
  const auto result = test::runCommand("CLM3D_DATA=" + (dir / "empty-data").string() + " " +
                                       (test::binaryDir() / "bin" / "clm3d").string() +
                                       " demo --real --out " + (dir / "demo").string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("franck.mp4"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("file not found"), std::string::npos) << result.output;
  // Nothing was started: no heads, no project.
  EXPECT_FALSE(std::filesystem::exists(dir / "demo" / "heads"));
}

}  // namespace
}  // namespace clm3d
