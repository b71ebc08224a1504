// The tracks CSV table: column layout, round trip with missing poses and points, and the
// messages for broken files (file, line and column named).
#include "core/track/track_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "core/common/error.hpp"
#include "core/common/number_text.hpp"
#include "core/track/track_table_writer.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

TrackTable sampleTable() {
  TrackTable table;
  table.landmarkCount = 3;
  TrackRow first;
  first.frame = 0;
  first.timestamp = 0.0;
  first.success = true;
  first.confidence = 0.8123456789;
  first.view = 4;
  first.pose = Pose::fromDegrees(12.5, -33.25, 4.0, {1.5, -2.25, -812.125}, 1.0625);
  first.points.resize(2, 3);
  first.points << 1234.5678, 0.0, 3999.9999, 17.25, -3.5, 2048.0001;
  table.rows.push_back(first);

  TrackRow second;  // no fit: no pose, a missing point, a lost frame
  second.frame = 2;
  second.timestamp = 0.066667;
  second.success = false;
  second.confidence = -0.25;
  second.view = -1;
  second.points.resize(2, 3);
  second.points << 10.0, kNan, 30.0, 11.0, kNan, 31.0;
  table.rows.push_back(second);
  return table;
}

TEST(TrackTable, HeaderAndCellsFollowTheDocumentedLayout) {
  const auto text = formatTrackTable(sampleTable());
  const auto firstBreak = text.find('\n');
  EXPECT_EQ(text.substr(0, firstBreak),
            "frame,timestamp,success,confidence,view,tx,ty,tz,scale,pitch,yaw,roll,"
            "x_1,x_2,x_3,y_1,y_2,y_3");
  // Angles in degrees, pixels with four decimals, seconds with six.
  EXPECT_NE(text.find("\n0,0.000000,1,0.812345679,4,1.5,-2.25,-812.125,1.0625,12.5,-33.25,4,"
                      "1234.5678,0.0000,3999.9999,17.2500,-3.5000,2048.0001\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\n2,0.066667,0,-0.25,-1,,,,,,,,10.0000,,30.0000,11.0000,,31.0000\n"),
            std::string::npos)
      << text;
}

TEST(TrackTable, RoundTripsIncludingMissingValues) {
  const auto table = sampleTable();
  test::TempDir dir;
  const auto path = dir / "tracks.csv";
  writeTrackTable(path, table);
  const auto back = readTrackTable(path);

  ASSERT_EQ(back.landmarkCount, 3);
  ASSERT_EQ(back.rows.size(), 2u);
  for (std::size_t r = 0; r < 2; ++r) {
    const auto& a = table.rows[r];
    const auto& b = back.rows[r];
    EXPECT_EQ(b.frame, a.frame);
    EXPECT_NEAR(b.timestamp, a.timestamp, 1e-7);
    EXPECT_EQ(b.success, a.success);
    EXPECT_NEAR(b.confidence, a.confidence, 1e-8);
    EXPECT_EQ(b.view, a.view);
    ASSERT_EQ(b.pose.has_value(), a.pose.has_value());
    if (a.pose) {
      EXPECT_NEAR((b.pose->translation - a.pose->translation).norm(), 0.0, 1e-9);
      EXPECT_NEAR(b.pose->scale, a.pose->scale, 1e-12);
      EXPECT_NEAR(b.pose->pitch, a.pose->pitch, 1e-9);
      EXPECT_NEAR(b.pose->yaw, a.pose->yaw, 1e-9);
      EXPECT_NEAR(b.pose->roll, a.pose->roll, 1e-9);
    }
    ASSERT_EQ(b.points.cols(), 3);
    for (int i = 0; i < 3; ++i) {
      for (int axis = 0; axis < 2; ++axis) {
        if (std::isnan(a.points(axis, i))) {
          EXPECT_TRUE(std::isnan(b.points(axis, i)));
        } else {
          EXPECT_NEAR(b.points(axis, i), a.points(axis, i), 5.1e-5);
        }
      }
    }
  }
  // Written again, the text is identical: nothing drifts through a read.
  EXPECT_EQ(formatTrackTable(back), formatTrackTable(table));
}

TEST(TrackTable, VisibilityColumnsFollowThePointsAndRoundTrip) {
  TrackTable table = sampleTable();
  table.extraColumns = {"note"};
  table.rows[0].visibility = {Visibility::Visible, Visibility::Hidden, Visibility::Unknown};
  // Row 1 has no fit: its visibility stays empty (unknown), written as empty cells.
  const auto text = formatTrackTable(table);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "frame,timestamp,success,confidence,view,tx,ty,tz,scale,pitch,yaw,roll,"
            "x_1,x_2,x_3,y_1,y_2,y_3,visible_1,visible_2,visible_3,note");
  EXPECT_NE(text.find(",2048.0001,1,0,,\n"), std::string::npos) << text;
  EXPECT_NE(text.find(",31.0000,,,,\n"), std::string::npos) << text;

  const auto back = parseTrackTable(text, "t.csv");
  EXPECT_EQ(back.extraColumns, (std::vector<std::string>{"note"}));
  ASSERT_EQ(back.rows.size(), 2u);
  EXPECT_EQ(back.rows[0].visibility, table.rows[0].visibility);
  EXPECT_EQ(back.rows[1].visibility, std::vector<Visibility>(3, Visibility::Unknown));
  EXPECT_EQ(formatTrackTable(back), text);

  // Other tools' spellings, in any order.
  const auto other = parseTrackTable(
      "frame,success,visible_2,x_1,y_1,x_2,y_2,visible_1\n0,1,true,1,2,3,4,nan\n", "o.csv");
  EXPECT_EQ(other.rows[0].visibility,
            (std::vector<Visibility>{Visibility::Unknown, Visibility::Visible}));
  EXPECT_TRUE(other.extraColumns.empty());
}

TEST(TrackTable, ATableWithoutVisibilityColumnsLoadsWithVisibilityUnknown) {
  // A file written before the visible_k columns existed.
  const auto old = parseTrackTable(
      "frame,timestamp,success,confidence,view,tx,ty,tz,scale,pitch,yaw,roll,x_1,x_2,y_1,y_2\n"
      "0,0.000000,1,0.8,1,1,2,-800,1,0,10,0,1.0000,2.0000,3.0000,4.0000\n",
      "old.csv");
  ASSERT_EQ(old.rows.size(), 1u);
  EXPECT_TRUE(old.rows[0].visibility.empty());
  EXPECT_TRUE(old.extraColumns.empty());
  // Written again it stays without them: nothing claims a visibility nobody measured.
  EXPECT_EQ(formatTrackTable(old).find("visible_"), std::string::npos);
}

TEST(TrackTable, VisibilityColumnsAreAllOrNoneAndFlagsOnly) {
  const auto message = [](const std::string& text) {
    try {
      parseTrackTable(text, "v.csv");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("frame,success,x_1,y_1,x_2,y_2,visible_1\n0,1,1,2,3,4,1\n"),
            "v.csv:1: missing column visible_2");
  EXPECT_EQ(message("frame,success,x_1,y_1,visible_1\n0,1,1,2,yes\n"),
            "v.csv:2: column visible_1: \"yes\" is not 0 or 1");
  TrackTable table = sampleTable();
  table.rows[0].visibility = {Visibility::Visible};
  EXPECT_THROW(formatTrackTable(table), Error);
}

TEST(TrackTable, LandmarkConfidenceColumnsFollowTheVisibilityAndRoundTrip) {
  TrackTable table = sampleTable();
  table.rows[0].visibility = {Visibility::Visible, Visibility::Hidden, Visibility::Visible};
  table.rows[0].landmarkConfidence = {0.75, kNan, -0.125};
  const auto text = formatTrackTable(table);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "frame,timestamp,success,confidence,view,tx,ty,tz,scale,pitch,yaw,roll,"
            "x_1,x_2,x_3,y_1,y_2,y_3,visible_1,visible_2,visible_3,conf_1,conf_2,conf_3");
  EXPECT_NE(text.find(",1,0,1,0.75,,-0.125\n"), std::string::npos) << text;
  const auto back = parseTrackTable(text, "t.csv");
  ASSERT_EQ(back.rows[0].landmarkConfidence.size(), 3U);
  EXPECT_EQ(back.rows[0].landmarkConfidence[0], 0.75);
  EXPECT_TRUE(std::isnan(back.rows[0].landmarkConfidence[1]));
  EXPECT_EQ(back.rows[0].landmarkConfidence[2], -0.125);
  ASSERT_EQ(back.rows[1].landmarkConfidence.size(), 3U);  // a row without: all empty cells
  EXPECT_TRUE(std::isnan(back.rows[1].landmarkConfidence[0]));
  EXPECT_TRUE(back.extraColumns.empty());
  EXPECT_EQ(formatTrackTable(back), text);

  // Older tables have none, and stay without when written again.
  const auto old = parseTrackTable("frame,success,x_1,y_1\n0,1,1,2\n", "old.csv");
  EXPECT_TRUE(old.rows[0].landmarkConfidence.empty());
  EXPECT_EQ(formatTrackTable(old).find("conf_"), std::string::npos);
  // All or none, and numbers only.
  EXPECT_THROW(parseTrackTable("frame,success,x_1,y_1,x_2,y_2,conf_2\n0,1,1,2,3,4,1\n", "c.csv"),
               InputError);
  EXPECT_THROW(parseTrackTable("frame,success,x_1,y_1,conf_1\n0,1,1,2,high\n", "c.csv"),
               InputError);
  table.rows[0].landmarkConfidence = {0.5};
  EXPECT_THROW(formatTrackTable(table), Error);
}

TEST(TrackTable, HalfMissingPointIsWrittenAsMissing) {
  TrackTable table;
  table.landmarkCount = 1;
  TrackRow row;
  row.points.resize(2, 1);
  row.points << 5.0, kNan;
  table.rows.push_back(row);
  const auto back = parseTrackTable(formatTrackTable(table), "t.csv");
  EXPECT_TRUE(std::isnan(back.rows[0].points(0, 0)));
  EXPECT_TRUE(std::isnan(back.rows[0].points(1, 0)));
}

TEST(TrackTable, ReadsColumnsByNameInAnyOrderWithExtras) {
  const std::string text =
      "\xEF\xBB\xBFy_1,note,x_1,success,frame,x_2,y_2\r\n"
      "2.5,hello,1.5,1,7,nan,nan\r\n"
      "\r\n"
      "4,,3,false,8,5,6\r\n";
  const auto table = parseTrackTable(text, "other.csv");
  ASSERT_EQ(table.landmarkCount, 2);
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].frame, 7);
  EXPECT_TRUE(table.rows[0].success);
  EXPECT_EQ(table.rows[0].points(0, 0), 1.5);
  EXPECT_EQ(table.rows[0].points(1, 0), 2.5);
  EXPECT_TRUE(std::isnan(table.rows[0].points(0, 1)));
  EXPECT_FALSE(table.rows[0].pose.has_value());
  EXPECT_EQ(table.rows[0].view, -1);
  EXPECT_FALSE(table.rows[1].success);
  EXPECT_EQ(table.rows[1].points(1, 1), 6.0);
}

TEST(TrackTable, ExtraColumnsAreReadAndWrittenAfterThePoints) {
  const std::string text =
      "frame,success,note,x_1,y_1,keyframe\n"
      "0,1,hello,1,2,1\n"
      "1,0,,3,4,0\n";
  const auto table = parseTrackTable(text, "extra.csv");
  ASSERT_EQ(table.extraColumns, (std::vector<std::string>{"note", "keyframe"}));
  EXPECT_EQ(table.rows[0].extraCells, (std::vector<std::string>{"hello", "1"}));
  EXPECT_EQ(table.rows[1].extraCells, (std::vector<std::string>{"", "0"}));

  const auto written = formatTrackTable(table);
  EXPECT_EQ(written.substr(0, written.find('\n')),
            "frame,timestamp,success,confidence,view,tx,ty,tz,scale,pitch,yaw,roll,x_1,y_1,"
            "note,keyframe");
  EXPECT_NE(written.find(",1.0000,2.0000,hello,1\n"), std::string::npos) << written;
  EXPECT_EQ(formatTrackTable(parseTrackTable(written, "again.csv")), written);

  // A row with fewer cells than columns gets empty ones.
  TrackTable shorter = table;
  shorter.rows[0].extraCells = {"x"};
  EXPECT_NE(formatTrackTable(shorter).find(",x,\n"), std::string::npos);
}

TEST(TrackTable, WriterRejectsExtraColumnsItCannotWriteAsIs) {
  TrackTable table;
  table.landmarkCount = 1;
  table.rows.emplace_back();
  table.rows.back().points = Eigen::Matrix2Xd::Zero(2, 1);
  for (const char* name : {"", "a,b", "x_1", "frame", "q\"uote"}) {
    table.extraColumns = {name};
    EXPECT_THROW(formatTrackTable(table), Error) << name;
  }
  table.extraColumns = {"note", "note"};
  EXPECT_THROW(formatTrackTable(table), Error);
  table.extraColumns = {"note"};
  table.rows.back().extraCells = {"a,b"};
  EXPECT_THROW(formatTrackTable(table), Error);
  table.rows.back().extraCells = {"a", "b"};
  EXPECT_THROW(formatTrackTable(table), Error);
  table.rows.back().extraCells = {"x_2"};  // a cell may hold anything without quoting needs
  EXPECT_NO_THROW(formatTrackTable(table));
}

TEST(TrackTable, WriterRejectsRowsWithTheWrongPointCount) {
  TrackTable table;
  table.landmarkCount = 2;
  table.rows.emplace_back();
  table.rows.back().points.resize(2, 3);
  EXPECT_THROW(formatTrackTable(table), Error);
}

std::string parseError(const std::string& text) {
  try {
    parseTrackTable(text, "tracks.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(TrackTable, BadInputsNameFileLineAndColumn) {
  const std::string header = "frame,timestamp,success,confidence,view,x_1,y_1\n";
  struct Case {
    std::string text;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"", "tracks.csv: empty file"},
      {"\n  \n", "tracks.csv: empty file"},
      {"timestamp,success,x_1,y_1\n", "tracks.csv:1: missing column frame"},
      {"frame,success,x_1,y_1,x_2\n", "tracks.csv:1: missing column y_2"},
      {"frame,success,x_1,y_1,tx,ty\n", "tracks.csv:1: missing column tz"},
      {"frame,success,frame,x_1,y_1\n", "tracks.csv:1: column frame appears twice"},
      {header + "0,0,1,0.5,0,1.5,abc\n", "tracks.csv:2: column y_1: \"abc\" is not a number"},
      {header + "0,0,1,0.5,0,1.5\n", "tracks.csv:2: expected 7 cells (as in the header), found 6"},
      {header + "0,0,1,0.5,0,1.5,2,9\n", "tracks.csv:2: expected 7 cells"},
      {header + "0,0,1,0.5,0,1.5,2\n1.5,0,1,0.5,0,1,2\n",
       "tracks.csv:3: column frame: \"1.5\" is not a whole number"},
      {header + "-1,0,1,0.5,0,1,2\n", "tracks.csv:2: column frame: -1 is below 0"},
      {header + "0,0,yes,0.5,0,1,2\n", "tracks.csv:2: column success: \"yes\" is not 0 or 1"},
      {header + "0,0,1,0.5,0,,2\n", "tracks.csv:2: column x_1: empty, but the other"},
      {header + "0,0,1,0.5,0,1,2\n0,0,1,0.5,0,1,2\n",
       "tracks.csv:3: column frame: frame 0 already appears on line 2"},
      {header + "0,0,1,inf,0,1,2\n", "tracks.csv:2: column confidence: \"inf\" is not a number"},
      {"frame,success,tx,ty,tz,scale,pitch,yaw,roll,x_1,y_1\n0,1,1,2,,1,0,0,0,1,1\n",
       "tracks.csv:2: column tz: empty, but other pose cells are not"},
  };
  for (const auto& c : cases) {
    const auto message = parseError(c.text);
    EXPECT_EQ(message.rfind(c.expected, 0), 0u)
        << "input:\n"
        << c.text << "\nmessage: " << message << "\nexpected start: " << c.expected;
  }
}

// A multi-face table (clm3d track --faces) has a row per face and frame: a frame repeats with
// another face, not with the same one; the writer streams the face column.
TEST(TrackTable, AFaceColumnLetsAFrameRepeatOncePerFace) {
  const std::string header = "frame,timestamp,success,confidence,view,x_1,y_1,face\n";
  const TrackTable table = parseTrackTable(
      header + "0,0,1,0.5,0,1,2,0\n0,0,1,0.5,0,5,6,1\n1,0,1,0.5,0,1,2,0\n", "t.csv");
  ASSERT_EQ(table.rows.size(), 3u);
  EXPECT_EQ(table.extraColumns, std::vector<std::string>{"face"});
  EXPECT_EQ(table.rows[1].extraCells, std::vector<std::string>{"1"});
  EXPECT_EQ(
      parseError(header + "0,0,1,0.5,0,1,2,1\n0,0,1,0.5,0,5,6,1\n")
          .rfind("tracks.csv:3: column frame: frame 0 of face 1 already appears on line 2", 0),
      0u);

  std::ostringstream out;
  TrackTableWriter writer(out, 1, {"face"});
  TrackRow row = table.rows[1];
  writer.write(row);
  const TrackTable back = parseTrackTable(out.str(), "w.csv");
  ASSERT_EQ(back.rows.size(), 1u);
  EXPECT_EQ(back.rows[0].extraCells, std::vector<std::string>{"1"});
  row.extraCells = {"1", "2"};
  EXPECT_THROW(writer.write(row), Error);
}

TEST(TrackTable, MissingFileIsAnInputErrorNamingIt) {
  test::TempDir dir;
  try {
    readTrackTable(dir / "absent.csv");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("absent.csv"), std::string::npos) << e.what();
  }
}

TEST(TrackTable, HeaderOnlyIsAnEmptyTable) {
  const auto table = parseTrackTable(formatTrackTable(TrackTable{2, {}}), "t.csv");
  EXPECT_EQ(table.landmarkCount, 2);
  EXPECT_TRUE(table.rows.empty());
}

}  // namespace
}  // namespace clm3d
