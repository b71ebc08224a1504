// An evaluation of one or more trackers' outputs against one ground truth, as `clm3d eval` reports
// it: each prediction's error summary, the significance test between them (Welch's t-test for two,
// one-way ANOVA for three or more, on the per-frame errors), and the report as JSON (for scripts)
// and as a short text summary (for people). The file-level function is the only one reading files.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/eval/error_buckets.hpp"
#include "core/eval/face_pairing.hpp"
#include "core/eval/landmark_error.hpp"
#include "core/eval/statistics.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

struct Comparison {
  enum class Kind { None, Welch, Anova };
  Kind kind = Kind::None;
  WelchTTest welch;  // when kind == Welch (first prediction is "a")
  Anova anova;       // when kind == Anova
  // Why no test was computed (empty when one was, or when there is only one prediction).
  std::string note;
};

struct EvaluationReport {
  std::string schemeName;
  std::string truthSource;                // the truth files joined by ", "
  std::vector<std::string> truthSources;  // one per sequence
  EvalOptions options;
  std::vector<SequenceEvaluation> sequences;  // one per prediction (tracker)
  Comparison comparison;
  std::optional<BucketedErrors> buckets;  // when asked for
  // Per sequence (tracker), per truth file and face: how the truth's faces were paired with the
  // tracked ones (core/eval/face_pairing.hpp). Empty unless a truth or a prediction has a face
  // column; then each face pair is one of the pooled sequences.
  std::vector<std::vector<FacePairing>> faces;
};

// One tracker's predictions of several sequences: predictions[i] is its output for truth i.
struct TrackerFiles {
  std::string label;  // empty: the first prediction's file name without extension
  std::vector<std::filesystem::path> predictions;
};

// Groups `--pred` files by tracker for `truthCount` sequences: the first truthCount predictions
// are the first tracker's (in truth order), the next ones the second's, and so on. labels: empty or
// one per tracker. Throws InputError when the counts do not divide or match, saying what was given.
std::vector<TrackerFiles> groupPredictions(std::size_t truthCount,
                                           const std::vector<std::filesystem::path>& predictions,
                                           const std::vector<std::string>& labels);

// Two sequences: Welch's t-test; three or more: one-way ANOVA; over scoredFrameErrors(). When the
// data cannot be tested (too few frames, no spread) the kind is None and note says why.
Comparison compareSequences(const std::vector<SequenceEvaluation>& sequences);

// Reads the ground truth and each prediction (tracks CSV), evaluates and compares them. labels
// name the predictions (empty, or one per prediction; default: the file name without extension).
// InputError names the file at fault.
EvaluationReport evaluateTrackFiles(const std::filesystem::path& truth,
                                    const std::vector<std::filesystem::path>& predictions,
                                    const std::vector<std::string>& labels, const Scheme& scheme,
                                    const EvalOptions& options = {});

// Several sequences pooled per tracker (evaluateSequences): reads every truth once and each
// tracker's predictions, evaluates and compares the trackers, and with buckets (non-null) breaks
// the errors down by that truth column (its column and absolute flag override options.keyColumn
// and keyAbsolute). InputError names the file at fault.
EvaluationReport evaluateTrackFiles(const std::vector<std::filesystem::path>& truths,
                                    const std::vector<TrackerFiles>& trackers, const Scheme& scheme,
                                    const EvalOptions& options = {},
                                    const BucketSpec* buckets = nullptr);

// {"format": "clm3d-evaluation", "version": 1, "scheme", "truth", "threshold", "predictions": [
// {"label", "file", "frames": {...}, "error": {mean, median, sd, min, max}, "convergence_rate",
// "points_within_threshold", "mean_point_error", "motion": {"jitter", "jitter_frames",
// "nmj", "lag_frames"}, "regions": [...], "cdf": [...], "per_frame": [{"frame", "error",
// "success", "converged", "jitter", "nmj", "sequence"}]}], "comparison": {...} or null,
// "truths": [...], and with buckets "buckets": {"column", "absolute", "edges", "predictions":
// [{"label", "outside", "buckets": [{"low", "high", "frames", "scored", "mean", "median",
// "convergence_rate", "points_within_threshold", "regions"}]}]}}. Each prediction has "files" too.
// NaN is null.
std::string formatReportJson(const EvaluationReport& report);
// Written atomically.
void writeReportJson(const std::filesystem::path& path, const EvaluationReport& report);

// The numbers of the text report as strings (locale-independent), for every view that shows
// them (the studio's table), so a figure reads the same everywhere: errors (and jitter) with four
// decimals, shares as percentages with one, p-values fixed or scientific; "n/a" when not finite.
std::string formatErrorValue(double value);
std::string formatFrames(double frames);  // two decimals (a lag in frames)
std::string formatShare(double share);
std::string formatPValue(double p);
// The report's significance-test line (Welch's t-test, one-way ANOVA, or why there is none),
// without a line break; empty for a single prediction.
std::string formatComparison(const EvaluationReport& report);

// A few lines per prediction: frames, mean/median/SD error, convergence rate, points within the
// threshold, per-region means, jitter, NMJ and lag; then the test; then the buckets' tables.
std::string formatReportText(const EvaluationReport& report);
// "  truth face 0: tracked face 1 (120 frames), 0 id switches" per face (formatReportText).
std::string formatFacePairings(const std::vector<FacePairing>& faces);

// The buckets as Markdown tables (docs/evaluation.md): per tracker the mean and median error,
// convergence and points within the threshold (frames in brackets) per bucket, then the regions'
// mean point error per tracker and bucket.
std::string formatBucketsText(const EvaluationReport& report);
// The same figures as CSV, one row per tracker and bucket: label,low,high,frames,scored,
// error_mean,error_median,convergence,within_threshold, then one column per region. Atomic.
std::string formatBucketsCsv(const EvaluationReport& report);
void writeBucketsCsv(const std::filesystem::path& path, const EvaluationReport& report);

}  // namespace clm3d
