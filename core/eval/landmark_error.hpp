// The landmark error of thesis eq. 5.1 and what is reported from it: for each ground-truth frame
// the distance of every predicted point from its true position divided by the true inter-ocular
// distance (the scheme's normalisation pair), the mean of those as the frame error, per-region
// means (figure 5.13), the share of points within 0.18 (figure 5.12), the convergence rate and
// the cumulative distribution of errors. Works on tables in memory; docs/evaluation.md explains
// every choice.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/scheme/scheme.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

struct EvalOptions {
  // A point whose normalised error is at most this is "found"; a frame whose mean error is below
  // it (and whose prediction exists and succeeded) has converged. Thesis figure 5.12: 0.18.
  double threshold = 0.18;
  // A frame reported as tracked (success) whose error exceeds this is a wrong success: the
  // tracker said it had the face when the fit was off (issue 12's measure of failure detection).
  double wrongAbove = 0.3;
  // The cumulative distributions are sampled at 0, cdfStep, ..., cdfMax.
  double cdfMax = 0.5;
  double cdfStep = 0.01;
  // When set, each frame's FrameError::key is this column of its ground-truth row
  // (trackColumnValue: e.g. "yaw"), or its absolute value with keyAbsolute, for bucketing
  // (error_buckets.hpp). A truth without the column is an InputError naming the file.
  std::string keyColumn;
  bool keyAbsolute = false;
};

// One ground-truth frame.
struct FrameError {
  int frame = 0;
  int sequence = 0;          // which truth/prediction pair of a pooled evaluation (0-based)
  bool normalised = false;   // the truth has both normalisation points, apart (else not scored)
  bool predicted = false;    // the prediction has a row for this frame
  bool success = false;      // ... and that row says success
  bool converged = false;    // predicted, success and error < threshold
  double interOcular = 0.0;  // true distance of the normalisation pair, pixels
  // Mean normalised error over the points present in both truth and prediction; NaN if none.
  double error = 0.0;
  // Per landmark, NaN where the truth or the prediction lacks the point.
  std::vector<double> pointErrors;
  // Per landmark, whether the truth has the point (the denominators of the shares).
  std::vector<bool> truePoints;
  // The truth's EvalOptions::keyColumn value in this frame; NaN without one.
  double key = std::numeric_limits<double>::quiet_NaN();
  // Motion of the prediction since the previous frame not explained by the truth's: the mean
  // over points of |(p_t - p_t-1) - (g_t - g_t-1)| / interOcular. NaN unless the truth has the
  // previous frame (frame - 1) and the prediction succeeded in both.
  double jitter = std::numeric_limits<double>::quiet_NaN();
  // NMJ, the normalised mean jitter of video face-alignment papers: the same frame-to-frame change
  // of the error, |(p_t - g_t) - (p_t-1 - g_t-1)|, averaged over the points but divided by the
  // truth's face size in frame t, sqrt(width x height) of the box around its points, which does
  // not shrink with yaw as the eye distance does (docs/evaluation.md). NaN when jitter is.
  double nmj = std::numeric_limits<double>::quiet_NaN();
  double faceSize = 0.0;  // sqrt of the area of the truth's point box, pixels; 0 if degenerate
  // The frame's mean pixel error over the same points divided by faceSize: the normalisation used
  // at large pose, where the eye distance shrinks as the head turns. NaN when error is or the box
  // is degenerate.
  double boxError = std::numeric_limits<double>::quiet_NaN();
};

struct RegionError {
  std::string name;
  RgbColour colour;
  int points = 0;                // point errors pooled (over scored frames)
  double mean = 0.0;             // NaN if points == 0
  double sd = 0.0;               // sample SD of the pooled point errors
  double withinThreshold = 0.0;  // found / true points of the region over normalised frames
};

struct CdfSample {
  double threshold = 0.0;
  double frames = 0.0;  // share of normalised truth frames with error <= threshold
  double points = 0.0;  // share of true points (of normalised frames) with error <= threshold
};

struct ErrorSummary {
  int truthFrames = 0;       // rows of the ground truth
  int normalisedFrames = 0;  // of those, with a usable inter-ocular distance: the denominator
  int predictedFrames = 0;   // normalised frames the prediction has a row for
  int succeededFrames = 0;   // ... with success = 1
  int wrongSuccesses = 0;    // ... of those, with an error above EvalOptions::wrongAbove
  int scoredFrames = 0;      // ... with at least one point in common (any success value)
  int convergedFrames = 0;
  int extraPredictionRows = 0;  // prediction rows for frames the truth does not have (ignored)
  // Frame errors of the scored frames.
  double mean = 0.0, median = 0.0, sd = 0.0, min = 0.0, max = 0.0;
  double convergenceRate = 0.0;  // convergedFrames / normalisedFrames
  int truePoints = 0;            // points present in the truth over normalised frames
  int foundPoints = 0;           // of those, predicted with error <= threshold
  double withinThreshold = 0.0;  // foundPoints / truePoints
  double meanPointError = 0.0;   // mean of every pooled point error (figure 5.13's line)
  // Mean and median of the scored frames' boxError (FrameError), NaN when none has one.
  double meanBoxError = std::numeric_limits<double>::quiet_NaN();
  double medianBoxError = std::numeric_limits<double>::quiet_NaN();
  // succeededFrames / normalisedFrames: the share of the frames the tracker says it fitted.
  double fittedShare = std::numeric_limits<double>::quiet_NaN();
  // Mean of the frames' jitter (NaN when no frame has one) and how many frames had one.
  double jitter = std::numeric_limits<double>::quiet_NaN();
  int jitterFrames = 0;
  // Mean of the frames' NMJ over the same frame pairs (NaN when none), pooled like jitter.
  double nmj = std::numeric_limits<double>::quiet_NaN();
  // How many frames the prediction trails the truth by: the least-squares L in
  // p_t - g_t = -L (g_t - g_t-1) over the points of the frames with a jitter; 0 for a prediction
  // without lag, about 1 for one a frame late, NaN when the truth does not move.
  double lagFrames = std::numeric_limits<double>::quiet_NaN();
  std::vector<RegionError> regions;  // in scheme order
  std::vector<CdfSample> cdf;
};

struct SequenceEvaluation {
  std::string label;                 // a name for reports and legends
  std::string source;                // where the prediction came from (its files), for reports
  std::vector<std::string> sources;  // the prediction of each pooled sequence, in pair order
  std::vector<FrameError> frames;    // one per truth row, in frame order
  ErrorSummary summary;
};

// Throws InputError naming truthName if its landmark count differs from the scheme's or no truth
// frame has a usable inter-ocular distance, and naming predictionName if its count differs from
// the truth's.
SequenceEvaluation evaluateSequence(const TrackTable& truth, const TrackTable& prediction,
                                    const Scheme& scheme, const EvalOptions& options = {},
                                    const std::string& truthName = "ground truth",
                                    const std::string& predictionName = "prediction");

// One ground truth and a prediction of the same sequence, with names for messages and reports.
// The tables must outlive the call they are passed to.
struct TrackPair {
  const TrackTable* truth = nullptr;
  const TrackTable* prediction = nullptr;
  std::string truthName = "ground truth";
  std::string predictionName = "prediction";
};

// One tracker over several sequences, pooled: every pair is evaluated as evaluateSequence does
// (same checks, each naming its file), the frames are concatenated in pair order (FrameError::
// sequence says which pair) and summarised together; jitter and lag pool the frame pairs of every
// sequence (never across two). With more than one pair, a prediction with rows for frames its
// truth lacks is an InputError naming both files (the pairs are likely mixed up). source lists
// the prediction names joined by ", ".
SequenceEvaluation evaluateSequences(const std::vector<TrackPair>& pairs, const Scheme& scheme,
                                     const EvalOptions& options = {});

// The summary of any subset of an evaluation's frames (e.g. a bucket): every figure but the
// motion ones (jitter, NMJ and lag stay NaN, extraPredictionRows 0).
ErrorSummary summariseFrames(const std::vector<FrameError>& frames, const Scheme& scheme,
                             const EvalOptions& options = {});

// The errors of the scored frames, in frame order (the sample the statistics compare).
std::vector<double> scoredFrameErrors(const SequenceEvaluation& evaluation);

}  // namespace clm3d
