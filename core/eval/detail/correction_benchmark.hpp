// Issue 29's correction benchmark on real video: for each sequence (a video and its truth, e.g. a
// `clm3d synth --photo` sequence's truth.csv, or a video's frames marked by another landmarker as a
// stand-in truth), the video tracked with the general model, then the simulated annotator
// (core/eval/simulated_annotator.hpp) run with each strategy, the studio's re-track and `clm3d
// adapt`'s adaptation doing the tracking; and, for review-adapt, the error of the frames it never
// corrected tracked through its keyframes with the general model and with the model adapted to all
// of them. What `clm3d correction-bench` runs and prints; docs/studio-track.md has the table.
#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/eval/simulated_annotator.hpp"
#include "core/model/clm_model.hpp"
#include "core/track/tracker.hpp"
#include "core/train/model_adaptation.hpp"

namespace clm3d {

struct BenchmarkSequence {
  std::string label;
  std::filesystem::path video;
  // A tracks or ground-truth CSV, one row per frame from 0 (its length is the sequence's, at most
  // the video's); rows without points are not scored. 68 iBUG points are converted to the model's
  // thesis25 (as photo truths are, docs/landmarks.md).
  std::filesystem::path truth;
};

struct CorrectionBenchmarkSettings {
  AnnotatorSettings annotator;
  std::vector<AnnotatorStrategy> strategies{AnnotatorStrategy::InOrder, AnnotatorStrategy::Review,
                                            AnnotatorStrategy::ReviewAdapt};
  TrackerSettings tracker;
  AdaptSettings adapt;
};

struct StrategyResult {
  AnnotatorRun run;
  double seconds = 0.0;
};

struct SequenceBenchmark {
  BenchmarkSequence sequence;
  int frames = 0;                                                // frames benchmarked
  double startError = std::numeric_limits<double>::quiet_NaN();  // first track, mean eq. 5.1
  // The frames of the sequence its video could not give (unreadableFramesWarning of the first
  // track: rows marked unreadable, left uncorrected and scored as lost); empty when none.
  std::string unreadable;
  std::vector<StrategyResult> strategies;  // in the settings' order
  // review-adapt: the scored frames it never corrected, and their mean error (eq. 5.1) tracked
  // through its keyframes (trackThroughKeyframes) with the general model and with the model
  // adapted to all its corrected frames; NaN without a review-adapt run that corrected a frame.
  int uncorrectedFrames = 0;
  int adaptedOnFrames = 0;
  double generalError = std::numeric_limits<double>::quiet_NaN();
  double adaptedError = std::numeric_limits<double>::quiet_NaN();
};

// Runs the benchmark on one sequence. `generalPath` is the model's file (named in the adapted
// models' provenance). Progress stages "LABEL: tracking" and "LABEL: STRATEGY: ...". InputError
// naming the file for an unreadable video or truth, a truth longer than the video or of another
// landmark count than the model's; Cancelled when cancelled.
SequenceBenchmark benchmarkSequence(const ClmModel& general,
                                    const std::filesystem::path& generalPath,
                                    const BenchmarkSequence& sequence,
                                    const CorrectionBenchmarkSettings& settings,
                                    const ProgressCallback& progress = {},
                                    const CancelToken* cancel = nullptr);

// The truth of a sequence for `model`: its table's rows, frames 0..n-1, converted to the model's
// scheme when it has the 68 iBUG points and the model thesis25. InputError naming the file.
TrackTable loadBenchmarkTruth(const std::filesystem::path& truth, const ClmModel& model);

// The tables of docs/studio-track.md: per sequence and strategy (frames corrected, drags,
// fallbacks, adaptations, re-tracks, whether capped, time), totals per strategy, the ratio of
// review-adapt's corrections to in-order's, and the error of the frames review-adapt never
// corrected, general against adapted.
std::string formatCorrectionBenchmark(const std::vector<SequenceBenchmark>& results,
                                      const AnnotatorSettings& settings);
// One CSV row per sequence and strategy: sequence, frames, scored, start_error, strategy,
// wrong_at_start, corrected, drags, fallbacks, adaptations, retracks, retracked_frames,
// wrong_at_end, capped, seconds, uncorrected_frames, general_error, adapted_error (the last three
// on review-adapt rows), corrected_frames (space-separated, in order).
std::string correctionBenchmarkCsv(const std::vector<SequenceBenchmark>& results);

}  // namespace clm3d
