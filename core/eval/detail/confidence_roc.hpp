// How well a fit's confidence tells right fits from wrong ones (issue 12, failure detection): the
// ROC of accepting a fit when its confidence is at least a threshold, over fits whose true error is
// known (a folder evaluation of `clm3d fit --images` outputs, whose summary.csv holds the
// confidences). A fit is wrong when its error exceeds `wrongAbove` (eye-centre normalised).
// `clm3d eval-points --truth-dir --pred-dir ... --roc` reports it (docs/evaluation.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/eval/point_folder_error.hpp"

namespace clm3d {

struct ScoredFit {
  double confidence = 0.0;
  double error = 0.0;  // eq. 5.1 over the chosen points
};

struct RocPoint {
  double threshold = 0.0;
  double rightAccepted = 0.0;  // share of right fits with confidence >= threshold
  double wrongAccepted = 0.0;  // share of wrong fits with confidence >= threshold
};

struct ConfidenceRoc {
  double wrongAbove = 0.15;
  int right = 0;
  int wrong = 0;
  double auc = 0.0;              // probability that a right fit scores above a wrong one
  std::vector<RocPoint> points;  // one per distinct confidence, threshold descending
  // The highest threshold that still accepts at least this share of the right fits (0.95), and
  // the share of wrong fits it accepts: the operating point a tracker would use.
  RocPoint atRightShare(double share) const;
};

ConfidenceRoc confidenceRoc(const std::vector<ScoredFit>& fits, double wrongAbove);

// What one threshold does (a fit accepted when its confidence is at least `threshold`): right fits
// kept, wrong ones (error above wrongAbove) accepted, and of the fits more than farAbove off (0.3:
// a tracked frame that far off is `clm3d eval`'s wrong success) those accepted. Issue 27 asks the
// tracker's default to keep at least 97% of the right fits and accept at most 1% of the wrong.
struct ThresholdCounts {
  double threshold = 0.5;
  double wrongAbove = 0.15;
  double farAbove = 0.3;
  int right = 0, rightKept = 0;
  int wrong = 0, wrongAccepted = 0;
  int far = 0, farAccepted = 0;
};
ThresholdCounts countsAt(const std::vector<ScoredFit>& fits, double threshold, double wrongAbove,
                         double farAbove);
// "at confidence >= T: keeps K of R right fits, accepts A of W wrong ones and F of N more than
// 0.3 off".
std::string formatThresholdCounts(const ThresholdCounts& counts);

// The fits of every method of a folder report that has a summary.csv (the batch fit's: columns
// image and confidence) in its prediction folder, paired with their errors. InputError naming the
// summary for a malformed one; methods without a summary are skipped.
std::vector<ScoredFit> scoredFitsFromSummaries(const PointFolderReport& report);

// "confidence ROC over N fits (R right, W wrong: error > E): AUC A; accepting 95% of the right
// fits (confidence >= T) accepts X% of the wrong ones" and the same at 90% and 99%.
std::string formatConfidenceRoc(const ConfidenceRoc& roc);

}  // namespace clm3d
