// The confidence ROC: a confidence that ranks every right fit above every wrong one has AUC 1, a
// reversed one 0, ties count half; the operating point that keeps a share of the right fits; and
// fits whose error or confidence is not finite are left out.
#include "core/eval/detail/confidence_roc.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace clm3d {
namespace {

TEST(ConfidenceRoc, PerfectReversedAndTiedConfidences) {
  const std::vector<ScoredFit> perfect{{0.9, 0.02}, {0.8, 0.05}, {0.3, 0.4}, {0.1, 0.9}};
  const ConfidenceRoc a = confidenceRoc(perfect, 0.15);
  EXPECT_EQ(a.right, 2);
  EXPECT_EQ(a.wrong, 2);
  EXPECT_DOUBLE_EQ(a.auc, 1.0);
  const RocPoint all = a.atRightShare(1.0);
  EXPECT_DOUBLE_EQ(all.threshold, 0.8);
  EXPECT_DOUBLE_EQ(all.wrongAccepted, 0.0);

  const std::vector<ScoredFit> reversed{{0.1, 0.02}, {0.2, 0.05}, {0.8, 0.4}, {0.9, 0.9}};
  EXPECT_DOUBLE_EQ(confidenceRoc(reversed, 0.15).auc, 0.0);

  const std::vector<ScoredFit> tied{{0.5, 0.02}, {0.5, 0.4}};
  EXPECT_DOUBLE_EQ(confidenceRoc(tied, 0.15).auc, 0.5);
}

TEST(ConfidenceRoc, OperatingPointAndNonFiniteFits) {
  std::vector<ScoredFit> fits;
  for (int i = 0; i < 20; ++i) fits.push_back({0.5 + 0.02 * i, 0.05});  // right: 0.50..0.88
  for (int i = 0; i < 10; ++i) fits.push_back({0.2 + 0.04 * i, 0.5});   // wrong: 0.20..0.56
  fits.push_back({std::numeric_limits<double>::quiet_NaN(), 0.05});
  const ConfidenceRoc roc = confidenceRoc(fits, 0.15);
  EXPECT_EQ(roc.right, 20);
  EXPECT_EQ(roc.wrong, 10);
  const RocPoint p = roc.atRightShare(0.95);  // 19 of 20 right fits: threshold 0.52
  EXPECT_NEAR(p.threshold, 0.52, 1e-9);
  EXPECT_NEAR(p.wrongAccepted, 0.2, 1e-9);  // the wrong fits at 0.52 and 0.56
  EXPECT_GT(roc.auc, 0.9);
  EXPECT_LT(roc.auc, 1.0);
  EXPECT_NE(formatConfidenceRoc(roc).find("AUC"), std::string::npos);
}

TEST(ConfidenceRoc, OneClassOnlyHasNoCurve) {
  const ConfidenceRoc roc = confidenceRoc({{0.9, 0.01}, {0.4, 0.02}}, 0.15);
  EXPECT_EQ(roc.wrong, 0);
  EXPECT_TRUE(roc.points.empty());
}

// The counts at one threshold, by hand: right fits (error up to 0.15) kept at confidence 0.5 or
// more, wrong ones accepted, and of the wrong ones those more than 0.3 off; a NaN is left out.
TEST(ConfidenceRoc, CountsAtOneThreshold) {
  const std::vector<ScoredFit> fits{
      {0.9, 0.02}, {0.5, 0.10}, {0.49, 0.05}, {0.95, 0.20},
      {0.3, 0.25}, {0.7, 0.6},  {0.1, 0.9},   {std::numeric_limits<double>::quiet_NaN(), 0.5}};
  const ThresholdCounts counts = countsAt(fits, 0.5, 0.15, 0.3);
  EXPECT_EQ(counts.right, 3);
  EXPECT_EQ(counts.rightKept, 2);  // 0.9 and 0.5; 0.49 is below
  EXPECT_EQ(counts.wrong, 4);
  EXPECT_EQ(counts.wrongAccepted, 2);  // 0.95 and 0.7
  EXPECT_EQ(counts.far, 2);
  EXPECT_EQ(counts.farAccepted, 1);  // 0.7 at 0.6
  EXPECT_EQ(formatThresholdCounts(counts),
            "  at confidence >= 0.5: keeps 2 of 3 right fits, accepts 2 of 4 wrong ones and 1 of 2 "
            "more than 0.3 off\n");
}

}  // namespace
}  // namespace clm3d
