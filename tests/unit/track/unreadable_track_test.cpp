// Tracking a video with frames it declares but cannot give (issue 27, item 5): every such frame
// gets a row marked unreadable, in frame order among the tracked ones; the summary lists them and
// the warning names the file and the counts; the tracks CSV carries a status column only then, and
// a table streamed before the frames were known is marked afterwards. The frames that could be
// read are tracked as before.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/track/ground_truth.hpp"
#include "core/track/keyframe_track.hpp"
#include "core/track/track_table_writer.hpp"
#include "core/track/tracker.hpp"
#include "tests/support/test_support.hpp"
#include "tests/support/tiny_model.hpp"
#include "tests/unit/video/damaged_video.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

struct Tracked {
  TrackTable table;
  TrackSummary summary;
  std::vector<int> seen;  // frames perFrame was called with
};

Tracked trackFile(const fs::path& video, const ClmModel& model) {
  Tracked out;
  out.summary = trackVideo(video, model, TrackerSettings{}, out.table,
                           [&out](const cv::Mat& frame, const TrackStep& step, Tracker&) {
                             EXPECT_EQ(test::numberOf(frame), step.row.frame);
                             out.seen.push_back(step.row.frame);
                           });
  return out;
}

// A 30-frame video cut to 60% of its bytes (at `cut`), tracked.
Tracked trackTruncated(const fs::path& dir, const fs::path& cut, const ClmModel& model) {
  test::writeNumberedVideo(dir / "whole.avi", 30);
  test::writeTruncatedCopy(dir / "whole.avi", cut, 0.6);
  return trackFile(cut, model);
}

TEST(UnreadableTrack, ATruncatedVideosMissingFramesAreRowsMarkedUnreadable) {
  const test::TempDir dir;
  const fs::path cut = dir / "cut.avi";
  const ClmModel model = test::makeTinyModel();
  const Tracked t = trackTruncated(dir.path(), cut, model);
  const int decoded = t.summary.frames;
  ASSERT_GT(decoded, 5);
  ASSERT_LT(decoded, 25);
  EXPECT_EQ(t.summary.declaredFrames, 30);
  ASSERT_EQ(t.summary.unreadable.size(), 1U);
  EXPECT_EQ(t.summary.unreadable[0], (FrameSpan{decoded, 30 - decoded}));
  EXPECT_EQ(t.summary.unreadableFrames(), 30 - decoded);
  EXPECT_EQ(static_cast<int>(t.seen.size()), decoded);  // no image, no perFrame
  ASSERT_EQ(t.table.rows.size(), 30U);
  for (int f = 0; f < 30; ++f) {
    const TrackRow& row = t.table.rows[static_cast<std::size_t>(f)];
    EXPECT_EQ(row.frame, f);
    EXPECT_EQ(row.unreadable, f >= decoded) << f;
    if (row.unreadable) {
      EXPECT_FALSE(row.success);
      EXPECT_FALSE(row.pose);
      EXPECT_FALSE(row.points.allFinite());
      EXPECT_EQ(row.points.cols(), model.shape.pointCount());
      EXPECT_NEAR(row.timestamp, f / 25.0, 1e-9);
    }
  }
  const std::string warning = unreadableFramesWarning(cut, t.summary);
  EXPECT_EQ(warning, cut.string() + ": the container declares 30 frames but " +
                         std::to_string(decoded) + " could be decoded; frames " +
                         std::to_string(decoded) +
                         "-29 are unreadable (no image: marked unreadable in the tracks)");
}

// A 30-frame video with a stretch of bytes zeroed in its middle, written into `dir`.
fs::path damagedInTheMiddle(const fs::path& dir) {
  test::writeNumberedVideo(dir / "whole.mkv", 30);
  const fs::path damaged = dir / "damaged.mkv";
  test::writeDamagedCopy(dir / "whole.mkv", damaged, 0.5, 3000);
  return damaged;
}

TEST(UnreadableTrack, DamagedFramesInTheMiddleKeepEveryRowInItsPlace) {
  const test::TempDir dir;
  const fs::path damaged = damagedInTheMiddle(dir.path());
  const ClmModel model = test::makeTinyModel();
  const Tracked t = trackFile(damaged, model);
  ASSERT_EQ(t.table.rows.size(), 30U);
  ASSERT_FALSE(t.summary.unreadable.empty());
  int unreadable = 0;
  for (int f = 0; f < 30; ++f) {
    EXPECT_EQ(t.table.rows[static_cast<std::size_t>(f)].frame, f);
    unreadable += t.table.rows[static_cast<std::size_t>(f)].unreadable ? 1 : 0;
  }
  EXPECT_EQ(unreadable, t.summary.unreadableFrames());
  EXPECT_EQ(t.summary.frames + unreadable, 30);
  EXPECT_EQ(static_cast<int>(t.seen.size()), t.summary.frames);
  const std::string warning = unreadableFramesWarning(damaged, t.summary);
  EXPECT_NE(warning.find("declares 30 frames but " + std::to_string(t.summary.frames) +
                         " could be decoded; frames " + formatFrameSpans(t.summary.unreadable)),
            std::string::npos)
      << warning;
}

// Through the keyframes (the studio's Adapt, the correction benchmark): a damaged frame in the
// middle is a row marked unreadable in its place, so every later row stays on its own frame (the
// loop of reads before counted rows, not frames, and shifted every row after the damage).
TEST(UnreadableTrack, KeyframeTrackingKeepsEveryRowOnItsFrameAndStopsAtTheTruthsEnd) {
  const test::TempDir dir;
  const fs::path damaged = damagedInTheMiddle(dir.path());
  const ClmModel model = test::makeTinyModel();
  const Tracked plain = trackFile(damaged, model);
  ASSERT_FALSE(plain.summary.unreadable.empty());
  const int firstUnreadable = plain.summary.unreadable.front().first;
  ASSERT_GT(firstUnreadable, 3);

  GroundTruthSet truth = GroundTruthSet::fromTrack(plain.table, 30);
  Eigen::Matrix2Xd corrected = Eigen::Matrix2Xd::Constant(2, model.shape.pointCount(), 20.0);
  for (int k = 0; k < corrected.cols(); ++k) corrected(0, k) += k;
  truth.setKeyframe(2, corrected);
  std::vector<int> seen;
  TrackTable table;
  const TrackSummary summary = trackThroughKeyframes(
      damaged, model, TrackerSettings{}, truth,
      [&table](TrackRow&& row) { table.rows.push_back(std::move(row)); },
      [&seen](const cv::Mat& frame, const TrackStep& step, Tracker&) {
        EXPECT_EQ(test::numberOf(frame), step.row.frame);
        seen.push_back(step.row.frame);
      });
  ASSERT_EQ(table.rows.size(), 30U);
  for (int f = 0; f < 30; ++f) {
    const TrackRow& row = table.rows[static_cast<std::size_t>(f)];
    EXPECT_EQ(row.frame, f);
    EXPECT_EQ(row.unreadable, plain.table.rows[static_cast<std::size_t>(f)].unreadable) << f;
  }
  EXPECT_EQ(summary.unreadable, plain.summary.unreadable);
  EXPECT_TRUE(table.rows[2].points.isApprox(corrected));  // the keyframe as given
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 2), 0);  // and not tracked
  EXPECT_EQ(static_cast<int>(seen.size()), summary.frames - 1);

  // A truth shorter than the video: its frames only, nothing reported missing beyond it.
  GroundTruthSet first(GroundTruthSet::fromTrack(plain.table, 30));
  first.table.rows.resize(3);
  first.keyframe.resize(3);
  const std::vector<TrackRow> rows =
      trackThroughKeyframes(damaged, model, TrackerSettings{}, first, {}, nullptr, nullptr);
  TrackSummary limited;
  trackThroughKeyframes(damaged, model, TrackerSettings{}, first, {}, nullptr, &limited);
  EXPECT_EQ(rows.size(), 3U);
  EXPECT_EQ(limited.frames, 3);
  EXPECT_EQ(limited.declaredFrames, 3);
  EXPECT_TRUE(limited.unreadable.empty());
}

TEST(UnreadableTrack, AnIntactVideoHasNoUnreadableRowAndNoStatusColumn) {
  const test::TempDir dir;
  test::writeNumberedVideo(dir / "clip.avi", 12);
  const ClmModel model = test::makeTinyModel();
  const Tracked t = trackFile(dir / "clip.avi", model);
  EXPECT_TRUE(t.summary.unreadable.empty());
  EXPECT_TRUE(unreadableFramesWarning(dir / "clip.avi", t.summary).empty());
  EXPECT_EQ(t.table.rows.size(), 12U);
  EXPECT_EQ(formatTrackTable(t.table).find("status"), std::string::npos);
}

TEST(UnreadableTrack, TheCsvMarksThemAndReadsThemBack) {
  const test::TempDir dir;
  const fs::path cut = dir / "cut.avi";
  const ClmModel model = test::makeTinyModel();
  const Tracked t = trackTruncated(dir.path(), cut, model);
  const std::string text = formatTrackTable(t.table);
  const std::string header = text.substr(0, text.find('\n'));
  EXPECT_TRUE(header.ends_with(",status")) << header;
  const TrackTable back = parseTrackTable(text, "tracks.csv");
  ASSERT_EQ(back.rows.size(), 30U);
  EXPECT_TRUE(back.extraColumns.empty());
  for (std::size_t f = 0; f < 30; ++f)
    EXPECT_EQ(back.rows[f].unreadable, t.table.rows[f].unreadable);

  // What `clm3d track` does: rows streamed without the column, then marked. Every cell stays as
  // streamed; only the status column is added.
  const fs::path streamed = dir / "streamed.csv";
  std::string expected;
  {
    std::ostringstream out;
    TrackTableWriter writer(out, model.shape.pointCount());
    for (TrackRow row : t.table.rows) {
      row.unreadable = false;
      writer.write(row);
    }
    test::writeFile(streamed, out.str());
    std::istringstream lines(out.str());
    std::string line;
    for (int k = -1; std::getline(lines, line); ++k) {
      const bool unreadable = k >= 0 && t.table.rows[static_cast<std::size_t>(k)].unreadable;
      expected += line + (k < 0 ? ",status" : unreadable ? ",unreadable" : ",") + "\n";
    }
  }
  markUnreadableFrames(streamed, t.summary.unreadable);
  EXPECT_EQ(test::readFile(streamed), expected);
}

}  // namespace
}  // namespace clm3d

namespace clm3d {
namespace {

TEST(UnreadableTrack, TheStatusColumnIsEmptyOrUnreadableAndOptional) {
  const std::string header = "frame,success,x_1,y_1,status\n";
  const TrackTable table = parseTrackTable(header + "0,1,3.5,4.5,\n1,0,,,unreadable\n", "t.csv");
  ASSERT_EQ(table.rows.size(), 2U);
  EXPECT_FALSE(table.rows[0].unreadable);
  EXPECT_TRUE(table.rows[1].unreadable);
  EXPECT_TRUE(table.extraColumns.empty());  // the tracker's own column, not an extra one
  EXPECT_FALSE(parseTrackTable("frame,success,x_1,y_1\n0,1,3.5,4.5\n", "t.csv").rows[0].unreadable);
  try {
    parseTrackTable(header + "0,1,3.5,4.5,lost\n", "t.csv");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "t.csv:2: column status: \"lost\" is not empty or unreadable");
  }
}

}  // namespace
}  // namespace clm3d
