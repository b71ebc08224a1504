// clm3d track --faces through the real binary: a video of two procedural heads crossing gives one
// row per face and frame with a face column whose ids stay with their heads; the default output
// has no face column; a bad count or --init with --faces is a usage error naming the option.
#include <gtest/gtest.h>

#include <map>

#include "core/model/model_file.hpp"
#include "core/track/track_table.hpp"
#include "core/video/video_writer.hpp"
#include "tests/support/test_support.hpp"
#include "tests/support/two_faces.hpp"

namespace clm3d {
namespace {

using test::runClm3d;

struct TwoFaceVideo {
  test::TempDir dir;
  std::string model, video;
  std::vector<test::TwoFaceFrame> frames;
};

void makeTwoFaceVideo(TwoFaceVideo& made) {
  made.model = (made.dir / "model.clm3d").string();
  saveModel(test::fitTestModel(), made.model);
  made.frames = test::twoFaceFrames(12, 10);
  made.video = (made.dir / "two.avi").string();
  VideoWriter writer(made.video, 640, 520, 25.0);
  for (const auto& frame : made.frames) writer.write(frame.image);
  writer.close();
}

const TwoFaceVideo& twoFaceVideo() {
  static TwoFaceVideo files;
  static const bool made = (makeTwoFaceVideo(files), true);
  (void)made;
  return files;
}

TEST(TrackFacesCli, EveryFaceGetsRowsWithAStableId) {
  const TwoFaceVideo& f = twoFaceVideo();
  const std::string tracks = (f.dir / "faces.csv").string();
  const auto result = runClm3d("track --quiet --faces all --model " + f.model + " --video " +
                               f.video + " --out " + tracks);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("2 faces"), std::string::npos) << result.output;
  const TrackTable table = readTrackTable(tracks);
  ASSERT_EQ(table.extraColumns, std::vector<std::string>{"face"});
  std::map<int, int> rowsPerFrame;
  std::map<std::string, bool> idIsTop;
  for (const TrackRow& row : table.rows) {
    ++rowsPerFrame[row.frame];
    ASSERT_EQ(row.extraCells.size(), 1u);
    if (!row.success) continue;
    const auto& frame = f.frames[static_cast<std::size_t>(row.frame)];
    const bool top = test::meanPointError(row.points, frame.top) <
                     test::meanPointError(row.points, frame.bottom);
    const auto [known, fresh] = idIsTop.emplace(row.extraCells[0], top);
    EXPECT_EQ(known->second, top) << "face " << row.extraCells[0] << " at frame " << row.frame;
  }
  EXPECT_EQ(idIsTop.size(), 2u);
  for (const auto& [frame, rows] : rowsPerFrame) EXPECT_EQ(rows, 2) << "frame " << frame;

  // clm3d eval pairs the truth's faces with the tracked ids, whatever their numbers.
  TrackTable truth;
  truth.landmarkCount = 25;
  truth.extraColumns = {"face"};
  for (std::size_t k = 0; k < f.frames.size(); ++k) {
    for (const auto& [points, face] :
         {std::pair(&f.frames[k].top, "0"), std::pair(&f.frames[k].bottom, "1")}) {
      TrackRow row;
      row.frame = static_cast<int>(k);
      row.timestamp = static_cast<double>(k) / 25.0;
      row.success = true;
      row.confidence = 1.0;
      row.points = *points;
      row.extraCells = {face};
      truth.rows.push_back(std::move(row));
    }
  }
  const std::string truthFile = (f.dir / "two-truth.csv").string();
  writeTrackTable(truthFile, truth);
  const auto eval = runClm3d("eval --truth " + truthFile + " --pred " + tracks);
  ASSERT_EQ(eval.exitCode, 0) << eval.output;
  EXPECT_NE(eval.output.find("truth face 0: tracked face"), std::string::npos) << eval.output;
  EXPECT_NE(eval.output.find("truth face 1: tracked face"), std::string::npos) << eval.output;
  EXPECT_EQ(eval.output.find("no tracked face"), std::string::npos) << eval.output;
  EXPECT_NE(eval.output.find(", 0 id switches"), std::string::npos) << eval.output;
  EXPECT_EQ(eval.output.find(", 1 id switches"), std::string::npos) << eval.output;

  const std::string one = (f.dir / "one.csv").string();
  const auto single =
      runClm3d("track --quiet --model " + f.model + " --video " + f.video + " --out " + one);
  ASSERT_EQ(single.exitCode, 0) << single.output;
  const TrackTable plain = readTrackTable(one);
  EXPECT_TRUE(plain.extraColumns.empty()) << "the default output keeps its columns";
  EXPECT_EQ(plain.rows.size(), f.frames.size());
}

TEST(TrackFacesCli, ABadCountOrInitWithFacesIsAUsageError) {
  const TwoFaceVideo& f = twoFaceVideo();
  const std::string out = (f.dir / "bad.csv").string();
  for (const std::string faces : {"0", "some", "-2", "3x"}) {
    const auto run = runClm3d("track --quiet --faces " + faces + " --model " + f.model +
                              " --video " + f.video + " --out " + out);
    EXPECT_NE(run.exitCode, 0) << faces;
    EXPECT_NE(run.output.find("--faces"), std::string::npos) << run.output;
  }
  const auto init = runClm3d("track --quiet --faces 2 --init start.pts --model " + f.model +
                             " --video " + f.video + " --out " + out);
  EXPECT_NE(init.exitCode, 0);
  EXPECT_NE(init.output.find("--init"), std::string::npos) << init.output;
}

}  // namespace
}  // namespace clm3d
