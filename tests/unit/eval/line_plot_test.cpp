// The generic line chart and the CSV reader behind `clm3d plot`: series grouped, filtered and
// sorted from a table, drawn in their colours, and bad tables rejected naming file and line.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>

#include "core/common/error.hpp"
#include "core/eval/eval_plots.hpp"
#include "core/eval/line_series_csv.hpp"
#include "tests/support/image_checks.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

const char* kTable =
    "identities,held_out,augmentation,error\n"
    "20,james,on,0.20\n"
    "1,james,on,0.30\n"
    "5,james,on,0.25\n"
    "1,james,off,0.35\n"
    "5,james,off,nan\n"
    "20,james,off,0.22\n"
    "1,lee,on,0.40\n";

int countNear(const cv::Mat& image, const cv::Scalar& colour) {
  int count = 0;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const auto p = image.at<cv::Vec3b>(y, x);
      if (std::abs(p[0] - colour[0]) < 4 && std::abs(p[1] - colour[1]) < 4 &&
          std::abs(p[2] - colour[2]) < 4) {
        ++count;
      }
    }
  }
  return count;
}

TEST(LineSeriesCsv, GroupsFiltersSkipsMissingAndSortsByX) {
  test::TempDir dir;
  test::writeFile(dir / "t.csv", kTable);
  SeriesSelection selection{"identities", "error", {"held_out", "augmentation"}, {}};
  const auto series = readLineSeriesCsv(dir / "t.csv", selection);
  ASSERT_EQ(series.size(), 3u);
  EXPECT_EQ(series[0].label, "james, on");
  ASSERT_EQ(series[0].points.size(), 3u);
  EXPECT_DOUBLE_EQ(series[0].points[0].x, 1.0);
  EXPECT_DOUBLE_EQ(series[0].points[0].y, 0.30);
  EXPECT_DOUBLE_EQ(series[0].points[2].x, 20.0);
  EXPECT_EQ(series[1].label, "james, off");
  EXPECT_EQ(series[1].points.size(), 2u);  // the nan row is skipped
  EXPECT_EQ(series[2].label, "lee, on");

  selection.where = {{"held_out", "james"}, {"augmentation", "off"}};
  const auto filtered = readLineSeriesCsv(dir / "t.csv", selection);
  ASSERT_EQ(filtered.size(), 1u);
  EXPECT_EQ(filtered[0].label, "james, off");
}

TEST(LineSeriesCsv, BadTablesNameFileLineAndColumn) {
  test::TempDir dir;
  const auto messageOf = [&](const std::string& text, SeriesSelection selection) {
    test::writeFile(dir / "bad.csv", text);
    try {
      readLineSeriesCsv(dir / "bad.csv", selection);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const SeriesSelection plain{"x", "y", {}, {}};
  EXPECT_NE(messageOf("x,y\n1,2\n3\n", plain).find("bad.csv:3: 1 cells, the header has 2"),
            std::string::npos)
      << messageOf("x,y\n1,2\n3\n", plain);
  EXPECT_NE(messageOf("x,y\n1,abc\n", plain).find("bad.csv:2: column y: 'abc' is not a number"),
            std::string::npos);
  EXPECT_NE(messageOf("x,y\n1,2\n", {"x", "z", {}, {}}).find("no column 'z' (y)"),
            std::string::npos);
  EXPECT_NE(messageOf("x,y\n1,nan\n", plain).find("no row to plot"), std::string::npos);
  EXPECT_NE(messageOf("", plain).find("no header row"), std::string::npos);
  EXPECT_THROW(readLineSeriesCsv(dir / "absent.csv", plain), InputError);
}

TEST(LinePlot, DrawsEverySeriesInItsColourOnALogAxis) {
  const std::vector<LineSeries> series = {{"a", {{1, 0.3}, {5, 0.25}, {20, 0.2}, {43, 0.18}}},
                                          {"b", {{1, 0.35}, {20, 0.22}}}};
  const auto image = plotLines(series, {"error against identities", "identities", "error", true});
  ASSERT_FALSE(image.empty());
  EXPECT_GE(image.cols, 900);
  EXPECT_GT(countNear(image, cv::Scalar(180, 119, 31)), 500);  // first series: blue
  EXPECT_GT(countNear(image, cv::Scalar(14, 127, 255)), 500);  // second: orange
  // A single series draws no orange.
  const auto one = plotLines({series[0]}, {"t", "x", "y", false});
  EXPECT_EQ(countNear(one, cv::Scalar(14, 127, 255)), 0);
}

// True if the outermost pixels are all white: nothing drawn runs off the picture.
TEST(LinePlot, ALongTitleWidensThePictureInsteadOfRunningOffIt) {
  const std::string title(120, 'W');
  const auto image = plotLines({{"a", {{1, 0.3}, {5, 0.25}}}}, {title, "x", "y", true});
  EXPECT_GT(image.cols, 960);
  EXPECT_TRUE(borderIsWhite(image));
  EXPECT_TRUE(borderIsWhite(plotLines({{"a", {{1, 0.3}, {5, 0.25}}}}, {"short", "x", "y", false})));
}

TEST(LinePlot, RejectsNothingToPlotAndNonPositiveLogX) {
  EXPECT_THROW(plotLines({{"empty", {}}}, {}), std::invalid_argument);
  EXPECT_THROW(plotLines({{"zero", {{0.0, 1.0}}}}, {"t", "x", "y", true}), std::invalid_argument);
  EXPECT_NO_THROW(plotLines({{"zero", {{0.0, 1.0}}}}, {"t", "x", "y", false}));
}

}  // namespace
}  // namespace clm3d
