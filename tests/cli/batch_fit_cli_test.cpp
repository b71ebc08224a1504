// clm3d fit over many images through the real binary (core/track/batch_fit): a folder of
// procedural-head renders with an unreadable image and a faceless one among them (an error row and
// a no-face row, the batch goes on, exit 1 at the end), a list file with comments, relative paths
// and start points from --init-dir (exit 0), the usage errors of mixing the two modes, and a fit
// the model's point check rejects (no points unless --keep-rejected; a rejected row in a batch).
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/model/model_file.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/refiner_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using test::runClm3d;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) result.push_back(line);
  return result;
}

double errorOf(const fs::path& pts, const test::FitScene& scene) {
  const LandmarkSet found = readLandmarks(pts, &Scheme::thesis25());
  Eigen::Matrix2Xd points(2, 25);
  for (int i = 0; i < 25; ++i) points.col(i) = found.point(i).head<2>();
  return test::meanPointError(points, scene.truthPoints) / scene.interOcular;
}

// A model, two renders of the held-out head, a grey image without a face and a "photo" that is
// text, in one folder; and the start points of the two renders in another.
struct BatchFiles {
  test::TempDir dir;
  fs::path model, images, starts;
  test::FitScene turned, frontal;
  BatchFiles() {
    model = dir / "model.clm3d";
    saveModel(test::fitTestModel(), model);
    images = dir / "images";
    starts = dir / "starts";
    fs::create_directories(images);
    fs::create_directories(starts);
    turned = test::makeFitScene(test::fitTestModel(), 0.0, 15.0, test::kHeldOutHead, 70.0);
    frontal = test::makeFitScene(test::fitTestModel(), 0.0, 0.0, test::kHeldOutHead, 70.0);
    writeImage(images / "a-turned.png", turned.image);
    writeImage(images / "b-frontal.jpg", frontal.image);
    writeImage(images / "c-blank.png", cv::Mat(240, 320, CV_8UC3, cv::Scalar(90, 90, 90)));
    test::writeFile(images / "d-broken.jpg", "this is text, not a JPEG\n");
    test::writeFile(images / "notes.txt", "not an image: left out of the batch\n");
    for (const auto& [name, scene] :
         {std::pair{"a-turned", &turned}, std::pair{"b-frontal", &frontal}}) {
      LandmarkSet start(25, 2);
      for (int i = 0; i < 25; ++i) {
        start.set(i, Eigen::Vector2d(scene->truthPoints.col(i) + Eigen::Vector2d(3.0, -2.0)));
      }
      writeLandmarks(starts / (std::string(name) + ".pts"), start, Scheme::thesis25());
    }
  }
};

const BatchFiles& batchFiles() {
  static const BatchFiles files;
  return files;
}

TEST(BatchFitCli, FolderWithAnUnreadableImageGivesAnErrorRowAndExitsOne) {
  const BatchFiles& f = batchFiles();
  const fs::path out = f.dir / "folder-out";
  const auto result = runClm3d("fit --model " + f.model.string() + " --images " +
                               f.images.string() + " --out-dir " + out.string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  // Progress per image on stderr, the broken image named in the final message.
  EXPECT_TRUE(test::contains(result.output, "fit 1/4 a-turned.png ")) << result.output;
  EXPECT_TRUE(test::contains(result.output, "fit 4/4 d-broken.jpg error")) << result.output;
  EXPECT_TRUE(test::contains(result.output, "1 of 4 images could not be fitted")) << result.output;
  EXPECT_TRUE(test::contains(result.output, "d-broken.jpg")) << result.output;

  const auto rows = lines(test::readFile(out / "summary.csv"));
  ASSERT_EQ(rows.size(), 5U) << test::readFile(out / "summary.csv");
  EXPECT_EQ(rows[0],
            "image,status,fit_ms,detect_ms,confidence,search_confidence,view_pitch,view_yaw,"
            "iterations,converged,probability_source,view_probability,error");
  EXPECT_TRUE(test::contains(rows[1], "a-turned.png,ok,")) << rows[1];
  // A model trained from renders only: the probability is the built-in curve's, no view check.
  EXPECT_TRUE(test::contains(rows[1], ",built-in NCC curve,,")) << rows[1];
  EXPECT_TRUE(test::contains(rows[2], "b-frontal.jpg,ok,")) << rows[2];
  EXPECT_TRUE(test::contains(rows[3], "c-blank.png,no-face,")) << rows[3];
  EXPECT_TRUE(test::contains(rows[3], "no face found")) << rows[3];
  EXPECT_TRUE(test::contains(rows[4], "d-broken.jpg,error,,,,,,,,")) << rows[4];
  EXPECT_TRUE(test::contains(rows[4], "d-broken.jpg")) << rows[4];
  // An ok row has fit and detection times and 25 points written beside the summary.
  EXPECT_FALSE(test::contains(rows[1], "ok,,")) << rows[1];
  EXPECT_LT(errorOf(out / "a-turned.pts", f.turned), 0.12);
  EXPECT_LT(errorOf(out / "b-frontal.pts", f.frontal), 0.12);
  EXPECT_EQ(readLandmarks(out / "a-turned.pts").size(), 25);
  EXPECT_FALSE(fs::exists(out / "c-blank.pts"));
  EXPECT_FALSE(fs::exists(out / "d-broken.pts"));
}

TEST(BatchFitCli, ListFileWithCommentsRelativePathsAndStartPoints) {
  const BatchFiles& f = batchFiles();
  const fs::path list = f.dir / "list.txt";
  test::writeFile(list, "# renders of the held-out head\n\nimages/a-turned.png\n  " +
                            (f.images / "b-frontal.jpg").string() + "  \n# the end\n");
  const fs::path out = f.dir / "list-out";
  const auto result = runClm3d("fit --model " + f.model.string() + " --images " + list.string() +
                               " --init-dir " + f.starts.string() + " --out-dir " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "fitted 2 of 2 images")) << result.output;
  const auto rows = lines(test::readFile(out / "summary.csv"));
  ASSERT_EQ(rows.size(), 3U);
  // Started from points: no detection time.
  EXPECT_TRUE(test::contains(rows[1], "a-turned.png,ok,")) << rows[1];
  std::istringstream cells(rows[1]);
  std::vector<std::string> values;
  for (std::string cell; std::getline(cells, cell, ',');) values.push_back(cell);
  ASSERT_GE(values.size(), 9U) << rows[1];
  EXPECT_FALSE(values[2].empty()) << rows[1];  // fit_ms
  EXPECT_TRUE(values[3].empty()) << rows[1];   // detect_ms
  // The summary line gives the median of the ok rows' fit_ms (of two: their mean), to 0.1 ms.
  const auto fitMs = [&](const std::string& row) {
    return std::stod(row.substr(row.find(",ok,") + 4));
  };
  const double median = 0.5 * (fitMs(rows[1]) + fitMs(rows[2]));
  const std::string printed = result.output.substr(result.output.find("fit median ") + 11);
  EXPECT_NEAR(std::stod(printed), median, 0.051) << result.output;
  EXPECT_LT(errorOf(out / "a-turned.pts", f.turned), 0.08);
  EXPECT_LT(errorOf(out / "b-frontal.pts", f.frontal), 0.08);
}

TEST(BatchFitCli, AnImageWithoutStartPointsInTheInitFolderIsAnErrorRow) {
  const BatchFiles& f = batchFiles();
  const fs::path list = f.dir / "list-blank.txt";
  test::writeFile(list, "images/a-turned.png\nimages/c-blank.png\n");
  const fs::path out = f.dir / "init-out";
  const auto result =
      runClm3d("fit --quiet --model " + f.model.string() + " --images " + list.string() +
               " --init-dir " + f.starts.string() + " --out-dir " + out.string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_FALSE(test::contains(result.output, "fit 1/2")) << result.output;  // --quiet
  const std::string summary = test::readFile(out / "summary.csv");
  EXPECT_TRUE(test::contains(summary, "c-blank.png,error,")) << summary;
  EXPECT_TRUE(test::contains(summary, "no start points c-blank.pts")) << summary;
}

TEST(BatchFitCli, ModesAreMutuallyExclusiveAndBadFoldersNameThemselves) {
  const BatchFiles& f = batchFiles();
  const std::string model = " --model " + f.model.string();
  const auto both = runClm3d("fit" + model + " --image " + (f.images / "a-turned.png").string() +
                             " --images " + f.images.string() + " --out x.pts");
  EXPECT_EQ(both.exitCode, 2) << both.output;
  const auto neither = runClm3d("fit" + model + " --out x.pts");
  EXPECT_EQ(neither.exitCode, 2) << neither.output;
  EXPECT_TRUE(test::contains(neither.output, "--images")) << neither.output;
  const auto noOutDir = runClm3d("fit" + model + " --images " + f.images.string());
  EXPECT_EQ(noOutDir.exitCode, 2) << noOutDir.output;
  EXPECT_TRUE(test::contains(noOutDir.output, "--out-dir")) << noOutDir.output;
  const auto outWithImages =
      runClm3d("fit" + model + " --images " + f.images.string() + " --out-dir o --out x.pts");
  EXPECT_EQ(outWithImages.exitCode, 2) << outWithImages.output;
  const fs::path absent = f.dir / "absent-folder";
  const auto missing = runClm3d("fit" + model + " --images " + absent.string() + " --out-dir " +
                                (f.dir / "o").string());
  EXPECT_EQ(missing.exitCode, 1) << missing.output;
  EXPECT_TRUE(test::contains(missing.output, absent.string())) << missing.output;
  // Fits written beside the images would overwrite their mark-ups.
  const auto sameFolder = runClm3d("fit" + model + " --images " + f.images.string() +
                                   " --out-dir " + f.images.string());
  EXPECT_EQ(sameFolder.exitCode, 1) << sameFolder.output;
  EXPECT_TRUE(test::contains(sameFolder.output, "is the folder of the images"))
      << sameFolder.output;
  EXPECT_FALSE(fs::exists(f.images / "summary.csv"));
  const fs::path empty = f.dir / "empty-list.txt";
  test::writeFile(empty, "# nothing\n\n");
  const auto none = runClm3d("fit" + model + " --images " + empty.string() + " --out-dir " +
                             (f.dir / "o").string());
  EXPECT_EQ(none.exitCode, 1) << none.output;
  EXPECT_TRUE(test::contains(none.output, "empty-list.txt")) << none.output;
}

// A model with a point check, searching a photo of noise from a face's points: the check rejects
// the fit. One image exits 1 naming the reason and writes no points, unless --keep-rejected; in a
// batch it is a rejected row and the batch exits 0.
TEST(BatchFitCli, AFitTheCheckRejectsWritesNoPointsUnlessKept) {
  const test::TempDir dir;
  ClmModel model = test::fitTestModel();
  model.refiner = test::photoRefiner();
  const fs::path modelPath = dir / "checked.clm3d";
  saveModel(model, modelPath);
  const test::FitScene scene = test::makeFitScene(model, 0.0, 0.0, test::kHeldOutHead);
  const fs::path images = dir / "images";
  const fs::path starts = dir / "starts";
  fs::create_directories(images);
  fs::create_directories(starts);
  test::savePhoto(starts, "noise", scene);  // the face's points as noise.pts
  fs::remove(starts / "noise.png");
  cv::Mat noise(scene.image.size(), scene.image.type());
  cv::randu(noise, 0, 255);
  writeImage(images / "noise.png", noise);

  const std::string single = "fit --model " + modelPath.string() + " --image " +
                             (images / "noise.png").string() + " --init " +
                             (starts / "noise.pts").string() + " --out ";
  const auto refused = runClm3d(single + (dir / "a.pts").string());
  EXPECT_EQ(refused.exitCode, 1) << refused.output;
  EXPECT_TRUE(test::contains(refused.output, "noise.png")) << refused.output;
  EXPECT_TRUE(test::contains(refused.output, "rejects the fit")) << refused.output;
  EXPECT_FALSE(fs::exists(dir / "a.pts"));
  const auto kept = runClm3d(single + (dir / "b.pts").string() + " --keep-rejected");
  EXPECT_EQ(kept.exitCode, 0) << kept.output;
  EXPECT_TRUE(test::contains(kept.output, "warning:")) << kept.output;
  EXPECT_TRUE(fs::exists(dir / "b.pts"));

  const fs::path out = dir / "batch";
  const auto batch = runClm3d("fit --model " + modelPath.string() + " --images " + images.string() +
                              " --init-dir " + starts.string() + " --out-dir " + out.string());
  EXPECT_EQ(batch.exitCode, 0) << batch.output;
  EXPECT_TRUE(test::contains(batch.output, "1 rejected by the point check")) << batch.output;
  EXPECT_FALSE(fs::exists(out / "noise.pts"));
  const std::vector<std::string> rows = lines(test::readFile(out / "summary.csv"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_TRUE(test::contains(rows[1], ",rejected,")) << rows[1];
}

}  // namespace
}  // namespace clm3d
