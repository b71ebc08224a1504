// The evaluation plots: written, of the expected size, on white with nothing touching the border,
// and with every series drawn in its own colour.
#include "core/eval/eval_plots.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "core/common/error.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/image_checks.hpp"
#include "tests/support/test_support.hpp"
#include "tests/unit/eval/eval_test_tables.hpp"

namespace clm3d {
namespace {

std::vector<SequenceEvaluation> twoSequences(const Scheme& scheme = Scheme::thesis25()) {
  const auto truth = test::truthTable(60);
  std::vector<SequenceEvaluation> sequences;
  for (const double base : {2.0, 7.0}) {
    auto prediction = test::shiftedTable(truth, [=](int f, int i) {
      return Eigen::Vector2d(base + 0.3 * ((f * 7 + i) % 11), 0.5 * (i % 3));
    });
    prediction.rows.erase(prediction.rows.begin() + 20, prediction.rows.begin() + 25);  // a gap
    sequences.push_back(evaluateSequence(truth, prediction, scheme));
  }
  sequences[0].label = "multi-view";
  sequences[1].label = "single-view";
  return sequences;
}

// Pixels within a few levels of colour (BGR).
int countColour(const cv::Mat& image, const cv::Scalar& colour) {
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

// True if the outermost `margin` pixels are all white: nothing drawn runs off the picture.
void expectGoodPlot(const cv::Mat& image, int minWidth) {
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.type(), CV_8UC3);
  EXPECT_GE(image.cols, minWidth);
  EXPECT_GE(image.rows, 500);
  EXPECT_TRUE(borderIsWhite(image));
  // Mostly white, but with a fair amount of drawing (axes, text, data).
  const int white = countColour(image, cv::Scalar(255, 255, 255));
  const int total = image.rows * image.cols;
  EXPECT_GT(white, total / 2);
  EXPECT_LT(white, total - 5000);
}

// The first two series colours (BGR) as the plots use them.
const cv::Scalar kBlue(180, 119, 31);
const cv::Scalar kOrange(14, 127, 255);

TEST(EvalPlots, CdfDrawsEverySeries) {
  const auto image = plotErrorCdf(twoSequences());
  expectGoodPlot(image, 900);
  EXPECT_GT(countColour(image, kBlue), 300);
  EXPECT_GT(countColour(image, kOrange), 300);
}

TEST(EvalPlots, ErrorPerFrameDrawsEverySeries) {
  const auto image = plotErrorPerFrame(twoSequences());
  expectGoodPlot(image, 900);
  EXPECT_GT(countColour(image, kBlue), 300);
  EXPECT_GT(countColour(image, kOrange), 300);
}

TEST(EvalPlots, ErrorPerFrameCopesWithHugeErrors) {
  const auto truth = test::truthTable(10);
  const auto far = test::offsetTable(truth, 600.0, 0.0);  // error 10: clipped at the top
  const auto image = plotErrorPerFrame({evaluateSequence(truth, far, Scheme::thesis25())});
  expectGoodPlot(image, 900);
  EXPECT_GT(countColour(image, kBlue), 100);
}

TEST(EvalPlots, RegionBarsHaveOneColourPerPrediction) {
  const auto image = plotRegionErrors(twoSequences());
  expectGoodPlot(image, 900);
  // Six groups (five regions and all points) of two bars, each bar tens of pixels tall.
  EXPECT_GT(countColour(image, kBlue), 2000);
  EXPECT_GT(countColour(image, kOrange), 2000);
}

TEST(EvalPlots, ManyRegionsWidenTheBarChart) {
  // iBUG 68: eight regions with longer names; the chart grows instead of overlapping labels.
  const auto& scheme = Scheme::ibug68();
  TrackTable truth;
  truth.landmarkCount = scheme.size();
  for (int f = 0; f < 3; ++f) {
    TrackRow row;
    row.frame = f;
    row.success = true;
    row.points.resize(2, scheme.size());
    for (int i = 0; i < scheme.size(); ++i) row.points.col(i) = Eigen::Vector2d(10.0 * i, 3.0 * i);
    truth.rows.push_back(row);
  }
  const auto prediction = test::offsetTable(truth, 4.0, 0.0);
  std::vector<SequenceEvaluation> sequences;
  for (int k = 0; k < 4; ++k) sequences.push_back(evaluateSequence(truth, prediction, scheme));
  const auto image = plotRegionErrors(sequences);
  expectGoodPlot(image, 960);
  EXPECT_GT(image.cols, plotRegionErrors(twoSequences()).cols);  // wider than for thesis25
}

TEST(EvalPlots, WritesThreeReadablePngs) {
  test::TempDir dir;
  EvaluationReport report;
  report.sequences = twoSequences();
  const auto files = writeEvaluationPlots(dir / "plots" / "nested", report);
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].filename(), "cdf.png");
  EXPECT_EQ(files[1].filename(), "error-per-frame.png");
  EXPECT_EQ(files[2].filename(), "regions.png");
  for (const auto& file : files) {
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    EXPECT_GT(std::filesystem::file_size(file), 5000u);
    const auto image = readImage(file);
    EXPECT_GE(image.cols, 900);
    EXPECT_GE(image.rows, 500);
  }
}

TEST(EvalPlots, UnwritableFolderIsAnInputError) {
  test::TempDir dir;
  test::writeFile(dir / "file", "x");
  EvaluationReport report;
  report.sequences = twoSequences();
  try {
    writeEvaluationPlots(dir / "file", report);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("file"), std::string::npos);
  }
}

}  // namespace
}  // namespace clm3d
