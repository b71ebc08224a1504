// Real-face accuracy in CI (ctest label `real`; the release pass runs it when ../shared/data is
// there, and it skips with a message when it is not). A small real-face model is trained at test
// time from the first LFPW training photos (never the 100 held-out ones, never a test photo; with
// procedural heads and ICT-FaceKit shapes), then, as a user runs the commands:
// - `clm3d fit --images` searches a fixed subset of the LFPW test photos from its own face
//   detector, and `clm3d eval-points` scores the fits on the 19 points with an LFPW counterpart;
// - the same on the first 40 AFLW test faces at |yaw| 30-60 degrees (aflw21/test.txt, yaw from its
//   index.csv), scored over the truth's face box on the shared points without the ear lobes;
// - `clm3d track --last 999` follows franck.mp4's first 1000 frames: every frame tracked, its
//   re-detections and frames in a side view (|yaw| of the view 30 or more) bounded.
// The bounds sit just above today's measured values (in the comments), so that a regression of 20%
// in accuracy fails. Seeds are fixed; the cost is in docs/testing.md. The model learns from LFPW
// (research use only): it lives in a temporary folder and is never kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/common/image_list.hpp"
#include "core/eval/yaw_bands.hpp"
#include "core/model/model_file.hpp"
#include "core/track/track_table.hpp"
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

// AFLW test faces: the first of test.txt in the |yaw| band 30-60 of its index.csv.
constexpr int kAflwFaces = 40;
// franck.mp4: its first frames, tracked.
constexpr int kFranckFrames = 1000;

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// `clm3d fit --images LIST` from the detector into dir/fits-NAME, then `clm3d eval-points` of
// those fits against the truth folder on `points`: the report's one method.
nlohmann::json fitAndScore(const fs::path& model, const fs::path& dir, const std::string& name,
                           const fs::path& list, const fs::path& truth, const std::string& points) {
  const fs::path fits = dir / ("fits-" + name);
  const auto start = std::chrono::steady_clock::now();
  const auto fitted =
      test::runClm3d("fit --model " + test::quoted(model) + " --images " + test::quoted(list) +
                     " --out-dir " + test::quoted(fits) + " --quiet");
  EXPECT_EQ(fitted.exitCode, 0) << fitted.output;
  std::cout << "[ " << name << ": fitted in " << secondsSince(start) << " s ]\n";
  const auto scored =
      test::runClm3d("eval-points --truth-dir " + test::quoted(truth) + " --pred-dir " +
                     test::quoted(fits) + " --points " + points + " --json");
  EXPECT_EQ(scored.exitCode, 0) << scored.output;
  if (scored.exitCode != 0) return {};
  const nlohmann::json report =
      nlohmann::json::parse(scored.output.substr(scored.output.find('{')));
  std::cout << "[ " << name << ": " << report.at("methods").at(0).dump() << " ]\n";
  return report;
}

TEST(RealFaces, ASmallModelTrainedOnLfpwFitsLfpwAndAflwTestPhotosAndTracksFranck) {
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

  // 3. Fit from the detector, as `clm3d fit --images` runs for a user, scored on the 18 trusted
  // points and the chin centre (docs/real-faces.md).
  const nlohmann::json report =
      fitAndScore(model, dir.path(), "lfpw", dir / "test.txt", dir / "truth", "1-18,22");
  ASSERT_FALSE(report.is_null());
  const nlohmann::json& fits = report.at("methods").at(0);
  ASSERT_EQ(report.at("images"), kTestPhotos);
  // Measured: 40 of 40 fitted, mean error 0.0474 (median 0.0473), 754 of 760 points (99.2%)
  // within 0.18 (0.0476 and 753 with the start grid and the refiner runs for every photo). A 20%
  // worse mean (0.0569) fails the first bound.
  EXPECT_GE(fits.at("predicted").get<int>(), kTestPhotos - 1);
  EXPECT_LT(fits.at("mean_error").get<double>(), 0.0520);
  EXPECT_GT(fits.at("found_share").get<double>(), 0.980);

  // 4. AFLW test faces turned 30-60 degrees: the first 40 of test.txt in that band.
  const fs::path aflw = data / "photos/aflw21";
  if (!fs::exists(aflw / "test.txt")) {
    std::cout << "[ " << aflw << " not found: the AFLW band is not measured ]\n";
  } else {
    const std::map<std::string, double> yaws = readPoseCsv(aflw / "index.csv");
    const std::vector<double> edges{0.0, 30.0, 60.0, 90.0};
    std::string band;
    int faces = 0;
    fs::create_directories(dir / "aflw-truth");
    for (const fs::path& image : listImages(aflw / "test.txt")) {
      const auto yaw = yaws.find(image.stem().string());
      if (yaw == yaws.end() || yawBandOf(yaw->second, edges) != 1) continue;
      band += image.string() + "\n";
      const fs::path pts = fs::path(image).replace_extension(".pts");
      fs::copy_file(pts, dir / "aflw-truth" / pts.filename());
      if (++faces == kAflwFaces) break;
    }
    ASSERT_EQ(faces, kAflwFaces);
    test::writeFile(dir / "aflw-30-60.txt", band);
    // The points AFLW and thesis25 share, without the ear lobes (19, 25), whose offset is a
    // definition apart (docs/real-faces.md): error over each truth's face box.
    const nlohmann::json turned = fitAndScore(
        model, dir.path(), "aflw-30-60", dir / "aflw-30-60.txt", dir / "aflw-truth", "1-18,20-24");
    ASSERT_FALSE(turned.is_null());
    const nlohmann::json& band30 = turned.at("methods").at(0);
    // Measured: 29 of 40 fitted (9 rejected by the point check, 2 without a face), mean error over
    // the face box 0.1441, 162 of 270 points (60.0%) within 0.18 of the eye distance. A 20% worse
    // error (0.173) fails the second bound.
    EXPECT_GE(band30.at("predicted").get<int>(), 27);
    EXPECT_LT(band30.at("mean_box_error").get<double>(), 0.158);
    EXPECT_GT(band30.at("found_share").get<double>(), 0.55);
  }

  // 5. franck.mp4's first 1000 frames, tracked as `clm3d track` runs for a user.
  const fs::path franck = data / "videos/franck.mp4";
  if (!fs::exists(franck)) {
    std::cout << "[ " << franck << " not found: the video is not tracked ]\n";
    return;
  }
  start = std::chrono::steady_clock::now();
  const auto tracked =
      test::runClm3d("track --model " + test::quoted(model) + " --video " + test::quoted(franck) +
                     " --last " + std::to_string(kFranckFrames - 1) + " --out " +
                     test::quoted(dir / "franck.csv") + " --quiet");
  ASSERT_EQ(tracked.exitCode, 0) << tracked.output;
  std::cout << "[ franck.mp4: " << secondsSince(start) << " s; " << tracked.output << " ]\n";
  const TrackTable table = readTrackTable(dir / "franck.csv");
  ASSERT_EQ(table.rows.size(), static_cast<std::size_t>(kFranckFrames));
  const ClmModel trainedModel = loadModel(model);
  int succeeded = 0;
  int sideView = 0;
  for (const TrackRow& row : table.rows) {
    succeeded += row.success ? 1 : 0;
    if (row.view >= 0 &&
        std::abs(trainedModel.views[static_cast<std::size_t>(row.view)].yawDeg) >= 30.0) {
      ++sideView;
    }
  }
  const auto detections = tracked.output.find(" detections");
  ASSERT_NE(detections, std::string::npos) << tracked.output;
  const int detected =
      std::stoi(tracked.output.substr(tracked.output.rfind(' ', detections - 1) + 1, detections));
  // Measured: 1000 of 1000 frames tracked, 1 detection (the first frame's: no re-detection), every
  // frame in the frontal view (0, 0).
  EXPECT_EQ(succeeded, kFranckFrames);
  EXPECT_LE(detected - 1, 3) << "re-detections";
  EXPECT_EQ(sideView, 0);
}

}  // namespace
}  // namespace clm3d
