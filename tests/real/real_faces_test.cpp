// Real-face accuracy in CI (ctest label `real`; the release pass runs it when ../shared/data is
// there, and it skips with a message when it is not). A small real-face model is trained at test
// time from the first LFPW training photos (never the 100 held-out ones, never a test photo; with
// procedural heads and ICT-FaceKit shapes), then `clm3d fit --images` searches a fixed subset of
// the LFPW test photos from its own face detector, as a user runs it, and `clm3d eval-points`
// scores the fits on the 19 points with an LFPW counterpart. The bounds sit just above today's
// measured values (in the comments), so that a regression of 20% in accuracy fails. Seeds are
// fixed; the cost is in docs/testing.md. The model learns from LFPW (research use only): it lives
// in a temporary folder and is never kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/common/image_list.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

// Training photos: the first ones in name order (the held-out split is the last 100 of the 805:
// resources/datasets/lfpw-train-heldout.txt).
constexpr int kTrainingPhotos = 300;
// Test photos: every 5th of the 224 in name order, the first 40 of those.
constexpr int kTestStride = 5;
constexpr int kTestPhotos = 40;

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(RealFaces, ASmallModelTrainedOnLfpwFitsLfpwTestPhotos) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const fs::path train = data / "photos/lfpw/train";
  const fs::path test = data / "photos/lfpw/test";
  const fs::path ict = data / "morphable/ict-facekit/ICT-FaceKit_FaceXModel.tar.xz";
  for (const fs::path& needed : {train, test, ict}) {
    if (!fs::exists(needed)) GTEST_SKIP() << needed << " not found";
  }
  test::TempDir dir;

  // 1. The model: the photos teach the patch experts and the point refiner; the procedural heads
  // and ICT-FaceKit's shapes give the 3D shape model and the renders of every view.
  const nlohmann::json manifest = {
      {"version", 1},
      {"name", "ci-real-small"},
      {"scheme", "thesis25"},
      {"procedural", {{{"seeds", "1-4"}, {"expressions", {"neutral"}}}}},
      {"ict_facekit",
       {{{"model", ict.string()},
         {"vertices", test::fixturePath("ict-facekit/thesis25_vertices.json").string()},
         {"identities", 100},
         {"expressions_per_sample", 2}}}},
      {"augmentation", {{"background", "clutter"}}},
      {"photos", {{{"folder", train.string()}, {"limit", kTrainingPhotos}}}}};
  test::writeFile(dir / "small.json", manifest.dump(2));
  const fs::path model = dir / "small.clm3d";
  auto start = std::chrono::steady_clock::now();
  const auto trained =
      test::runClm3d("train --dataset " + test::quoted(dir / "small.json") + " --out " +
                     test::quoted(model) + " --texture-max-modes 4 --seed 1");
  ASSERT_EQ(trained.exitCode, 0) << trained.output;
  std::cout << "[ trained in " << secondsSince(start) << " s ]\n";

  // 2. The fixed test subset, and its truth alone (eval-points counts a missing fit as a failure).
  const std::vector<fs::path> photos = listImages(test);
  ASSERT_EQ(photos.size(), 224u);
  std::string list;
  fs::create_directories(dir / "truth");
  for (int i = 0; i < kTestPhotos; ++i) {
    const fs::path& photo = photos[static_cast<std::size_t>(i * kTestStride)];
    list += photo.string() + "\n";
    const fs::path pts = fs::path(photo).replace_extension(".pts");
    fs::copy_file(pts, dir / "truth" / pts.filename());
  }
  test::writeFile(dir / "test.txt", list);

  // 3. Fit from the detector, as `clm3d fit --images` runs for a user.
  start = std::chrono::steady_clock::now();
  const auto fitted = test::runClm3d("fit --model " + test::quoted(model) + " --images " +
                                     test::quoted(dir / "test.txt") + " --out-dir " +
                                     test::quoted(dir / "fits") + " --quiet");
  ASSERT_EQ(fitted.exitCode, 0) << fitted.output;
  std::cout << "[ fitted " << kTestPhotos << " photos in " << secondsSince(start) << " s ]\n";

  // 4. Scored on the 18 trusted points and the chin centre (docs/real-faces.md).
  const auto scored =
      test::runClm3d("eval-points --truth-dir " + test::quoted(dir / "truth") + " --pred-dir " +
                     test::quoted(dir / "fits") + " --points 1-18,22 --json");
  ASSERT_EQ(scored.exitCode, 0) << scored.output;
  const nlohmann::json report =
      nlohmann::json::parse(scored.output.substr(scored.output.find('{')));
  const nlohmann::json& fits = report.at("methods").at(0);
  std::cout << "[ " << fits.dump() << " ]\n";
  ASSERT_EQ(report.at("images"), kTestPhotos);
  // Measured: 40 of 40 fitted, mean error 0.0474 (median 0.0473), 754 of 760 points (99.2%)
  // within 0.18 (0.0476 and 753 with the start grid and the refiner runs for every photo). A 20%
  // worse mean (0.0569) fails the first bound.
  EXPECT_GE(fits.at("predicted").get<int>(), kTestPhotos - 1);
  EXPECT_LT(fits.at("mean_error").get<double>(), 0.0520);
  EXPECT_GT(fits.at("found_share").get<double>(), 0.980);
}

}  // namespace
}  // namespace clm3d
