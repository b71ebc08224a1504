// The batch fit's parts that need no model: which files of a folder or lines of a list are images,
// where start points are found, and the summary table's cells (empty where there is no value,
// quoted where a message holds a comma or quote).
#include "core/track/batch_fit.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"
#include "core/scheme/landmark_file.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

TEST(BatchImages, AFolderGivesItsImagesSortedAndAListItsLines) {
  const test::TempDir dir;
  for (const char* name : {"b.JPG", "a.png", "c.jpeg", "d.ppm", "e.bmp", "notes.txt", "a.pts"}) {
    test::writeFile(dir / name, "x");
  }
  fs::create_directories(dir / "sub.png");  // a folder named like an image is not one
  const auto images = listImages(dir.path());
  ASSERT_EQ(images.size(), 5U);
  EXPECT_EQ(images[0].filename(), "a.png");
  EXPECT_EQ(images[1].filename(), "b.JPG");
  EXPECT_EQ(images[4].filename(), "e.bmp");

  test::writeFile(dir / "list.txt", "# comment\n\n  a.png \r\n/abs/x.jpg\nsub/y.png\n");
  const auto listed = listImages(dir / "list.txt");
  ASSERT_EQ(listed.size(), 3U);
  EXPECT_EQ(listed[0], dir / "a.png");
  EXPECT_EQ(listed[1], fs::path("/abs/x.jpg"));
  EXPECT_EQ(listed[2], dir / "sub/y.png");

  test::writeFile(dir / "empty.txt", "# nothing here\n");
  try {
    listImages(dir / "empty.txt");
    FAIL() << "no error for an empty list";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("empty.txt"), std::string::npos) << e.what();
  }
  EXPECT_THROW(listImages(dir / "absent"), InputError);
}

TEST(BatchImages, StartPointsArePtsThenLjsonThenCsv) {
  const test::TempDir dir;
  test::writeFile(dir / "x.csv", "x");
  test::writeFile(dir / "x.ljson", "x");
  EXPECT_EQ(findLandmarkFile(dir.path(), "x"), dir / "x.ljson");
  test::writeFile(dir / "x.pts", "x");
  EXPECT_EQ(findLandmarkFile(dir.path(), "x"), dir / "x.pts");
  EXPECT_FALSE(findLandmarkFile(dir.path(), "y").has_value());
}

TEST(BatchSummary, EmptyCellsForMissingValuesAndQuotedMessages) {
  ImageFitOutcome ok;
  ok.image = "a.png";
  ok.status = ImageFitStatus::Ok;
  ok.fitMilliseconds = 3.14159;
  ok.fit = FitResult{};
  ok.fit->probability = 0.5;
  ok.fit->searchScore = 0.25;
  ok.fit->iterations = 7;
  ok.fit->converged = true;
  ok.viewPitchDeg = 0.0;
  ok.viewYawDeg = -30.0;
  ok.fit->probabilitySource = ProbabilitySource::ViewCheck;
  ok.fit->viewProbability = 0.75;
  ImageFitOutcome bad;
  bad.image = "b, \"odd\".jpg";
  bad.status = ImageFitStatus::Error;
  bad.message = "b.jpg: cannot be read, or so";
  EXPECT_EQ(formatBatchFitSummary({ok, bad}),
            "image,status,fit_ms,detect_ms,confidence,search_confidence,view_pitch,view_yaw,"
            "iterations,converged,probability_source,view_probability,error\n"
            "a.png,ok,3.142,,0.500000,0.250000,0.0,-30.0,7,1,view check,0.750000,\n"
            "\"b, \"\"odd\"\".jpg\",error,,,,,,,,,,,\"b.jpg: cannot be read, or so\"\n");
}

}  // namespace
}  // namespace clm3d
