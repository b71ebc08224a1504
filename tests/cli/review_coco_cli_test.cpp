// clm3d truth's COCO keypoints export and import and clm3d review's list, through the real binary:
// a ground truth written as COCO and read back with its keyframes; a track with a low check, a
// jump and an outlier listed in rank order with their reasons; bad inputs exit 1 naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "core/common/number_text.hpp"
#include "core/track/ground_truth.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::runClm3d;

// 30 frames of thesis25 points (eye centres 60 pixels apart) drifting a pixel a frame, confidence
// 0.8: frame 8 has a low check, frames from 15 on are 18 pixels lower (a jump at 15), and point 12
// of frame 24 is 7 pixels off (an outlier).
void writeReviewTracks(const std::filesystem::path& path) {
  TrackTable table;
  table.landmarkCount = 25;
  for (int frame = 0; frame < 30; ++frame) {
    TrackRow row;
    row.frame = frame;
    row.timestamp = frame / 30.0;
    row.success = true;
    row.confidence = frame == 8 ? 0.25 : 0.8;
    row.points.resize(2, 25);
    for (int i = 0; i < 25; ++i) {
      row.points.col(i) = Eigen::Vector2d(200.0 + 4.0 * i + frame, 300.0 + (frame >= 15 ? 18 : 0));
    }
    row.points(0, 7) = 220.0 + frame;
    row.points(0, 10) = 280.0 + frame;
    if (frame == 24) row.points(1, 11) += 7.0;
    table.rows.push_back(row);
  }
  writeTrackTable(path, table);
}

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ReviewCli, ListsFramesWithTheirReasonsInRankOrder) {
  test::TempDir dir;
  writeReviewTracks(dir / "tracks.csv");
  const auto out = dir / "review.csv";
  const auto result =
      runClm3d("review --tracks " + (dir / "tracks.csv").string() + " --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("review: 3 of 30 frames listed"), std::string::npos)
      << result.output;
  const std::string csv = readText(out);
  // The jump (0.3 eye distances, twice its threshold), the low check ((1 - 0.25) / 0.5 = 1.5),
  // the outlier (7/60 = 0.117 against 0.1).
  EXPECT_NE(csv.find("\n1,15,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",jump,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n2,8,1.5,low-confidence,0.25,,low-confidence=0.25\n"), std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\n3,24,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("temporal-fit=0.1167@12"), std::string::npos) << csv;

  // Options from the table: a higher jump threshold and a cap.
  const auto fewer = runClm3d("review --tracks " + (dir / "tracks.csv").string() +
                              " --jump 0.5 --max-frames 1 --out " + out.string());
  ASSERT_EQ(fewer.exitCode, 0) << fewer.output;
  EXPECT_NE(readText(out).find("\n1,8,"), std::string::npos) << readText(out);
  EXPECT_EQ(readText(out).find("\n2,"), std::string::npos) << readText(out);

  // A ground truth's keyframes are left out.
  const auto truth = dir / "gt.csv";
  ASSERT_EQ(
      runClm3d("truth --in " + (dir / "tracks.csv").string() + " --out " + truth.string()).exitCode,
      0);
  GroundTruthSet set = loadGroundTruth(truth);
  set.keyframe[15] = true;
  saveGroundTruth(truth, set);
  const auto skipped = runClm3d("review --tracks " + truth.string() + " --out " + out.string());
  ASSERT_EQ(skipped.exitCode, 0) << skipped.output;
  EXPECT_EQ(readText(out).find("\n1,15,"), std::string::npos) << readText(out);
  EXPECT_NE(skipped.output.find("(1 keyframes left out)"), std::string::npos) << skipped.output;

  // Bad input: a range error is bad usage, a broken file names itself.
  EXPECT_EQ(runClm3d("review --tracks " + (dir / "tracks.csv").string() + " --window 1 --out " +
                     out.string())
                .exitCode,
            2);
  test::writeFile(dir / "broken.csv", "frame,success\n0,x\n");
  const auto broken =
      runClm3d("review --tracks " + (dir / "broken.csv").string() + " --out " + out.string());
  EXPECT_EQ(broken.exitCode, 1);
  EXPECT_NE(broken.output.find("broken.csv"), std::string::npos) << broken.output;
}

TEST(TruthCli, CocoExportAndImportRoundTrip) {
  test::TempDir dir;
  writeReviewTracks(dir / "tracks.csv");
  const auto csv = dir / "gt.csv";
  const auto coco = dir / "gt.json";
  // Frames 3 and 9 keyframes (by editing the set), then exported.
  ASSERT_EQ(
      runClm3d("truth --in " + (dir / "tracks.csv").string() + " --out " + csv.string()).exitCode,
      0);
  GroundTruthSet set = loadGroundTruth(csv);
  set.setKeyframe(3, set.table.rows[3].points);
  set.setKeyframe(9, set.table.rows[9].points);
  set.table.rows[5].points.col(2).setConstant(kNan);
  saveGroundTruth(csv, set);
  auto result = runClm3d("truth --in " + csv.string() + " --out " + csv.string() + " --coco " +
                         coco.string() + " --image-size 640x480");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("coco: " + coco.string() + " (30 images 640x480, scheme thesis25)"),
            std::string::npos)
      << result.output;
  const std::string json = readText(coco);
  EXPECT_NE(json.find("\"file_name\":\"frame_000029.png\""), std::string::npos);
  EXPECT_NE(json.find("\"left_eye_centre\""), std::string::npos);

  // Imported back: the same points and keyframes.
  const auto back = dir / "back.csv";
  result = runClm3d("truth --in " + coco.string() + " --out " + back.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const GroundTruthSet read = loadGroundTruth(back);
  ASSERT_EQ(read.frameCount(), 30);
  EXPECT_EQ(read.keyframe, set.keyframe);
  for (int f = 0; f < 30; ++f) {
    const auto& a = set.table.rows[static_cast<std::size_t>(f)].points;
    const auto& b = read.table.rows[static_cast<std::size_t>(f)].points;
    for (int i = 0; i < 25; ++i) {
      if (std::isnan(a(0, i))) {
        EXPECT_TRUE(std::isnan(b(0, i))) << f << " " << i;
      } else {
        EXPECT_NEAR(a(0, i), b(0, i), 1e-9) << f << " " << i;
        EXPECT_NEAR(a(1, i), b(1, i), 1e-9) << f << " " << i;
      }
    }
  }

  // Bad input: no size, a broken COCO file.
  result = runClm3d("truth --in " + csv.string() + " --out " + back.string() + " --coco " +
                    coco.string());
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("--coco needs the frames' size"), std::string::npos)
      << result.output;
  result = runClm3d("truth --in " + csv.string() + " --out " + back.string() + " --coco " +
                    coco.string() + " --image-size 640");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("--image-size: \"640\" is not WIDTHxHEIGHT"), std::string::npos)
      << result.output;
  test::writeFile(dir / "bad.json", R"({"categories": [], "images": [], "annotations": []})");
  result = runClm3d("truth --in " + (dir / "bad.json").string() + " --out " + back.string());
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("bad.json: field categories: no category has keypoints"),
            std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace clm3d
