// The evaluation report: which test compares the predictions, the JSON and text forms, and the
// file-level entry point's messages.
#include "core/eval/eval_report.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/common/error.hpp"
#include "tests/support/test_support.hpp"
#include "tests/unit/eval/eval_test_tables.hpp"

namespace clm3d {
namespace {

// A prediction whose frame f is off by base + spread * ((f * 7) % 5) pixels in x.
TrackTable noisyPrediction(const TrackTable& truth, double base, double spread) {
  return test::shiftedTable(
      truth, [=](int f, int) { return Eigen::Vector2d(base + spread * ((f * 7) % 5), 0.0); });
}

std::vector<SequenceEvaluation> threeSequences() {
  const auto truth = test::truthTable(20);
  std::vector<SequenceEvaluation> sequences;
  for (const double base : {1.0, 2.0, 6.0}) {
    sequences.push_back(
        evaluateSequence(truth, noisyPrediction(truth, base, 0.5), Scheme::thesis25()));
  }
  return sequences;
}

TEST(EvalReport, TwoPredictionsAreComparedWithWelchsTest) {
  auto sequences = threeSequences();
  sequences.pop_back();
  const auto comparison = compareSequences(sequences);
  ASSERT_EQ(comparison.kind, Comparison::Kind::Welch);
  const auto expected =
      welchTTest(scoredFrameErrors(sequences[0]), scoredFrameErrors(sequences[1]));
  EXPECT_DOUBLE_EQ(comparison.welch.t, expected.t);
  EXPECT_DOUBLE_EQ(comparison.welch.p, expected.p);
  EXPECT_LT(comparison.welch.t, 0.0);  // the first is better
  EXPECT_LT(comparison.welch.p, 0.01);
}

TEST(EvalReport, ThreeOrMorePredictionsAreComparedWithAnova) {
  const auto sequences = threeSequences();
  const auto comparison = compareSequences(sequences);
  ASSERT_EQ(comparison.kind, Comparison::Kind::Anova);
  EXPECT_EQ(comparison.anova.df1, 2.0);
  EXPECT_EQ(comparison.anova.df2, 57.0);
  EXPECT_LT(comparison.anova.p, 1e-6);
}

TEST(EvalReport, UntestableDataGivesANoteNotAnError) {
  const auto truth = test::truthTable(5);
  const std::vector<SequenceEvaluation> flat = {
      evaluateSequence(truth, test::offsetTable(truth, 1, 0), Scheme::thesis25()),
      evaluateSequence(truth, test::offsetTable(truth, 2, 0), Scheme::thesis25())};
  const auto comparison = compareSequences(flat);
  EXPECT_EQ(comparison.kind, Comparison::Kind::None);
  EXPECT_NE(comparison.note.find("no spread"), std::string::npos) << comparison.note;
  EXPECT_EQ(compareSequences({flat[0]}).kind, Comparison::Kind::None);
  EXPECT_TRUE(compareSequences({flat[0]}).note.empty());
}

TEST(EvalReport, JsonHoldsSummariesFramesAndTheTest) {
  EvaluationReport report;
  report.schemeName = "thesis25";
  report.truthSource = "gt.csv";
  report.sequences = threeSequences();
  report.sequences.pop_back();
  report.sequences[0].label = "multi";
  report.sequences[1].label = "single";
  report.comparison = compareSequences(report.sequences);
  const auto json = nlohmann::json::parse(formatReportJson(report));
  EXPECT_EQ(json["format"], "clm3d-evaluation");
  EXPECT_EQ(json["scheme"], "thesis25");
  EXPECT_DOUBLE_EQ(json["threshold"].get<double>(), 0.18);
  ASSERT_EQ(json["predictions"].size(), 2u);
  const auto& first = json["predictions"][0];
  EXPECT_EQ(first["label"], "multi");
  EXPECT_DOUBLE_EQ(first["error"]["mean"].get<double>(), report.sequences[0].summary.mean);
  EXPECT_DOUBLE_EQ(first["convergence_rate"].get<double>(), 1.0);
  EXPECT_EQ(first["frames"]["scored"], 20);
  EXPECT_EQ(first["regions"].size(), 5u);
  EXPECT_EQ(first["regions"][4]["name"], "jaw");
  EXPECT_EQ(first["cdf"].size(), 51u);
  EXPECT_EQ(first["per_frame"].size(), 20u);
  EXPECT_GT(report.sequences[0].summary.nmj, 0.0);  // the noise changes from frame to frame
  EXPECT_DOUBLE_EQ(first["motion"]["nmj"].get<double>(), report.sequences[0].summary.nmj);
  EXPECT_DOUBLE_EQ(first["per_frame"][3]["nmj"].get<double>(), report.sequences[0].frames[3].nmj);
  EXPECT_EQ(json["comparison"]["test"], "welch_t");
  EXPECT_DOUBLE_EQ(json["comparison"]["p"].get<double>(), report.comparison.welch.p);
}

TEST(EvalReport, JsonWritesMissingValuesAsNull) {
  const auto truth = test::truthTable(2);
  auto prediction = truth;
  prediction.rows.clear();
  EvaluationReport report;
  report.sequences = {evaluateSequence(truth, prediction, Scheme::thesis25())};
  const auto json = nlohmann::json::parse(formatReportJson(report));
  EXPECT_TRUE(json["predictions"][0]["error"]["mean"].is_null());
  EXPECT_TRUE(json["predictions"][0]["per_frame"][0]["error"].is_null());
  EXPECT_TRUE(json["comparison"].is_null());
}

TEST(EvalReport, TextSummaryNamesEveryPredictionAndTheTest) {
  EvaluationReport report;
  report.schemeName = "thesis25";
  report.truthSource = "gt.csv";
  report.sequences = threeSequences();
  report.sequences[0].label = "powell";
  report.comparison = compareSequences(report.sequences);
  const auto text = formatReportText(report);
  EXPECT_NE(text.find("ground truth: gt.csv (20 frames, scheme thesis25"), std::string::npos);
  EXPECT_NE(text.find("\npowell ("), std::string::npos) << text;
  EXPECT_NE(text.find("convergence rate 100.0%"), std::string::npos) << text;
  EXPECT_NE(text.find("left_eye "), std::string::npos);
  EXPECT_NE(text.find(", NMJ " + formatErrorValue(report.sequences[0].summary.nmj) + ", lag "),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("one-way ANOVA on frame errors: F(2, 57)"), std::string::npos) << text;
}

TEST(EvalReport, FilesAreReadEvaluatedAndLabelled) {
  test::TempDir dir;
  const auto truth = test::truthTable(6);
  writeTrackTable(dir / "gt.csv", truth);
  writeTrackTable(dir / "a.csv", noisyPrediction(truth, 1.0, 0.5));
  writeTrackTable(dir / "b.csv", noisyPrediction(truth, 3.0, 0.5));
  const auto report =
      evaluateTrackFiles(dir / "gt.csv", {dir / "a.csv", dir / "b.csv"}, {}, Scheme::thesis25());
  ASSERT_EQ(report.sequences.size(), 2u);
  EXPECT_EQ(report.sequences[0].label, "a");
  EXPECT_EQ(report.sequences[1].source, (dir / "b.csv").string());
  EXPECT_EQ(report.comparison.kind, Comparison::Kind::Welch);
  const auto labelled =
      evaluateTrackFiles(dir / "gt.csv", {dir / "a.csv"}, {"mine"}, Scheme::thesis25());
  EXPECT_EQ(labelled.sequences[0].label, "mine");
  EXPECT_THROW(evaluateTrackFiles(dir / "gt.csv", {dir / "a.csv"}, {"x", "y"}, Scheme::thesis25()),
               InputError);

  test::writeFile(dir / "broken.csv", "frame,success,x_1\n");
  try {
    evaluateTrackFiles(dir / "gt.csv", {dir / "a.csv", dir / "broken.csv"}, {}, Scheme::thesis25());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.csv:1: missing column y_1"), std::string::npos)
        << e.what();
  }
}

TEST(EvalReport, JsonIsWrittenToAFile) {
  test::TempDir dir;
  EvaluationReport report;
  report.sequences = threeSequences();
  report.comparison = compareSequences(report.sequences);
  writeReportJson(dir / "report.json", report);
  const auto json = nlohmann::json::parse(test::readFile(dir / "report.json"));
  EXPECT_EQ(json["predictions"].size(), 3u);
  EXPECT_EQ(json["comparison"]["test"], "one_way_anova");
}

}  // namespace
}  // namespace clm3d
