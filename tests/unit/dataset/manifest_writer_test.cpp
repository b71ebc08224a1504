// The manifest writer: what it writes loads back with the same sources (relative paths inside the
// folder, absolute outside), and sources it cannot write are an error, not silently dropped.
#include "core/dataset/manifest_writer.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

TEST(ManifestWriter, WritesWhatLoadManifestReadsBack) {
  const test::TempDir dir;
  const test::TempDir outside;
  fs::create_directories(dir / "heads");
  test::writeFile(dir / "heads/h1.obj", "v 0 0 0\n");
  test::writeFile(dir / "heads/h1.ljson", "{}");
  test::writeFile(outside / "scan.obj", "v 0 0 0\n");
  test::writeFile(outside / "scan.ljson", "{}");

  DatasetManifest manifest;
  manifest.name = "written \"quoted\" name";
  manifest.scans.push_back({dir / "heads/h1.obj", dir / "heads/h1.ljson", "h1", "smile"});
  ScanSource far{outside / "scan.obj", outside / "scan.ljson", "far", "neutral"};
  far.up = "+z";
  far.front = "-y";
  far.levelEyes = false;
  far.scale = 10.0;
  manifest.scans.push_back(far);
  manifest.procedural.push_back({{3, 4}, {"neutral", "smile"}, 256, 2.0});
  manifest.augmentation.noiseSd = 0.02;
  manifest.augmentation.shadows = true;
  const fs::path file = dir / "dataset.json";
  saveManifest(manifest, file);

  const std::string text = test::readFile(file);
  EXPECT_NE(text.find("\"heads/h1.obj\""), std::string::npos) << text;
  const DatasetManifest back = loadManifest(file);
  EXPECT_EQ(back.name, manifest.name);
  EXPECT_EQ(back.scheme, "thesis25");
  ASSERT_EQ(back.scans.size(), 2u);
  EXPECT_TRUE(fs::equivalent(back.scans[0].mesh, dir / "heads/h1.obj"));
  EXPECT_EQ(back.scans[0].subject, "h1");
  EXPECT_EQ(back.scans[0].expression, "smile");
  EXPECT_TRUE(fs::equivalent(back.scans[1].landmarks, outside / "scan.ljson"));
  EXPECT_EQ(back.scans[1].up, "+z");
  EXPECT_EQ(back.scans[1].front, "-y");
  EXPECT_FALSE(back.scans[1].levelEyes);
  EXPECT_DOUBLE_EQ(back.scans[1].scale, 10.0);
  ASSERT_EQ(back.procedural.size(), 1u);
  EXPECT_EQ(back.procedural[0].seeds, (std::vector<std::uint64_t>{3, 4}));
  EXPECT_EQ(back.procedural[0].expressions, (std::vector<std::string>{"neutral", "smile"}));
  EXPECT_EQ(back.procedural[0].textureSize, 256);
  EXPECT_DOUBLE_EQ(back.procedural[0].faceStepDegrees, 2.0);
  EXPECT_EQ(back.augmentation.background, AugmentationBackground::Clutter);
  EXPECT_DOUBLE_EQ(back.augmentation.noiseSd, 0.02);
  EXPECT_TRUE(back.augmentation.shadows);
}

TEST(ManifestWriter, RefusesSourcesItDoesNotWrite) {
  DatasetManifest manifest;
  manifest.name = "m";
  manifest.photos.push_back({});
  EXPECT_THROW(formatManifest(manifest, "/tmp"), Error);
  manifest.photos.clear();
  manifest.makehuman.push_back({});
  EXPECT_THROW(formatManifest(manifest, "/tmp"), Error);
}

}  // namespace
}  // namespace clm3d
