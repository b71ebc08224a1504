#include "core/eval/detail/correction_benchmark.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <utility>

#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"
#include "core/eval/landmark_error.hpp"
#include "core/geometry/camera.hpp"
#include "core/scheme/ibug68_conversion.hpp"
#include "core/track/ground_truth.hpp"
#include "core/track/keyframe_track.hpp"
#include "core/track/retrack.hpp"
#include "core/track/video_adaptation.hpp"
#include "core/video/video_reader.hpp"

namespace clm3d {
namespace {

std::vector<bool> presentPoints(const Eigen::Matrix2Xd& points) {
  std::vector<bool> present(static_cast<std::size_t>(points.cols()));
  for (int k = 0; k < points.cols(); ++k) {
    present[static_cast<std::size_t>(k)] = points.col(k).allFinite();
  }
  return present;
}

// The real tracker behind the annotator: the studio's re-track (retrackSpan from the state the
// corrected points give) with the general model, or with the adapted one once adapt() ran.
class VideoAnnotatorTracker final : public AnnotatorTracker {
 public:
  VideoAnnotatorTracker(const ClmModel& general, std::filesystem::path generalPath,
                        std::filesystem::path video, const CorrectionBenchmarkSettings& settings,
                        const CancelToken* cancel)
      : general_(general),
        generalPath_(std::move(generalPath)),
        video_(std::move(video)),
        settings_(settings),
        cancel_(cancel) {
    const VideoReader probe(video_);
    camera_ =
        Camera::fromVerticalFov(probe.width(), probe.height(), videoFovDeg(settings_.tracker));
  }

  SpanRetrack retrack(int /*corrected*/, const Eigen::Matrix2Xd& points,
                      const std::vector<int>& frames, const std::vector<TrackRow>& previous,
                      const RetrackRules& rules) override {
    SpanRetrack out;
    FitState state;
    try {
      state = stateFromPoints(model(), camera_, points, presentPoints(points));
    } catch (const InputError&) {
      return out;  // too few points to place the face: nothing re-tracked
    }
    retrackSpan(video_, model(), settings_.tracker, state, -1, frames, previous, rules, out, {}, {},
                cancel_);
    return out;
  }

  std::vector<TrackRow> adapt(const GroundTruthSet& truth) override {
    adapted_ = adaptTo(truth);
    return trackThroughKeyframes(video_, *adapted_, settings_.tracker, truth, {}, cancel_);
  }

  ClmModel adaptTo(const GroundTruthSet& truth) const {
    return adaptToVideo(general_, generalPath_, video_, truth, "correction-bench", settings_.adapt,
                        nullptr, {}, cancel_);
  }

 private:
  const ClmModel& model() const { return adapted_ ? *adapted_ : general_; }

  const ClmModel& general_;
  std::filesystem::path generalPath_, video_;
  const CorrectionBenchmarkSettings& settings_;
  const CancelToken* cancel_;
  Camera camera_;
  std::optional<ClmModel> adapted_;
};

// Mean eq. 5.1 error of `rows` over the truth rows of the frames that are not keyframes of
// `corrected` (NaN when none of them is scored).
double uncorrectedError(const TrackTable& truth, const std::vector<TrackRow>& rows,
                        const GroundTruthSet& corrected, const Scheme& scheme, int* frames) {
  TrackTable others = truth;
  std::erase_if(others.rows, [&](const TrackRow& row) {
    return corrected.keyframe[static_cast<std::size_t>(row.frame)];
  });
  TrackTable prediction = truth;
  prediction.rows = rows;
  try {
    const SequenceEvaluation evaluation = evaluateSequence(others, prediction, scheme);
    if (frames != nullptr) *frames = evaluation.summary.normalisedFrames;
    return evaluation.summary.mean;
  } catch (const InputError&) {
    return std::numeric_limits<double>::quiet_NaN();  // no frame left to score
  }
}

// A number for the CSV: empty when missing.
std::string csvNumber(double value, int digits) {
  if (!std::isfinite(value)) return "";
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

// The same for the tables: "-" for a missing value.
std::string fixed(double value, int digits) {
  std::string text = csvNumber(value, digits);
  return text.empty() ? "-" : text;
}

}  // namespace

TrackTable loadBenchmarkTruth(const std::filesystem::path& truth, const ClmModel& model) {
  TrackTable table = loadGroundTruth(truth).table;
  const Scheme scheme = model.scheme();
  if (table.landmarkCount == 68 && scheme.size() != 68 && scheme.name() == "thesis25") {
    for (TrackRow& row : table.rows) {
      LandmarkSet ibug(68, 2);
      for (int k = 0; k < 68; ++k) {
        if (row.points.col(k).allFinite()) ibug.set(k, Eigen::Vector2d(row.points.col(k)));
      }
      row.points = ibug68ToThesis25(ibug).matrix().topRows(2);
    }
    table.landmarkCount = scheme.size();
  }
  if (table.landmarkCount != scheme.size()) {
    throwInputError(truth, "has " + std::to_string(table.landmarkCount) +
                               " landmarks, the model's "
                               "scheme " +
                               scheme.name() + " has " + std::to_string(scheme.size()));
  }
  return table;
}

SequenceBenchmark benchmarkSequence(const ClmModel& general,
                                    const std::filesystem::path& generalPath,
                                    const BenchmarkSequence& sequence,
                                    const CorrectionBenchmarkSettings& settings,
                                    const ProgressCallback& progress, const CancelToken* cancel) {
  settings.annotator.validate();
  const Scheme scheme = general.scheme();
  SequenceBenchmark result;
  result.sequence = sequence;
  const TrackTable truth = loadBenchmarkTruth(sequence.truth, general);
  result.frames = static_cast<int>(truth.rows.size());
  {
    const VideoReader probe(sequence.video);
    if (probe.frameCount() > 0 && result.frames > probe.frameCount()) {
      throwInputError(sequence.truth, "has " + std::to_string(result.frames) +
                                          " frames, the video " + sequence.video.string() +
                                          " has " + std::to_string(probe.frameCount()));
    }
  }
  // Progress stages "LABEL: NAME WHAT" (NAME or WHAT may be empty).
  const auto stage = [&](const std::string& name) -> ProgressCallback {
    if (!progress) return {};
    return
        [&progress, prefix = sequence.label + ": " + name](double fraction, std::string_view what) {
          std::string text = prefix;
          if (!what.empty()) text += (text.back() == ' ' ? "" : " ") + std::string(what);
          progress(fraction, text);
        };
  };

  // The first track: every frame with the general model, no keyframes.
  TrackTable track = truth;
  TrackSummary firstTrack;
  track.rows = trackThroughKeyframes(sequence.video, general, settings.tracker,
                                     GroundTruthSet::fromTrack(truth, result.frames),
                                     stage("first track"), cancel, &firstTrack);
  result.unreadable = unreadableFramesWarning(sequence.video, firstTrack);
  result.startError = evaluateSequence(truth, track, scheme).summary.mean;

  for (const AnnotatorStrategy strategy : settings.strategies) {
    const auto start = std::chrono::steady_clock::now();
    VideoAnnotatorTracker tracker(general, generalPath, sequence.video, settings, cancel);
    StrategyResult done;
    done.run = simulateAnnotator(strategy, truth, track, scheme, tracker, settings.annotator,
                                 stage(""), cancel);
    if (strategy == AnnotatorStrategy::ReviewAdapt && done.run.corrected > 0) {
      const GroundTruthSet& corrected = done.run.result;
      const ClmModel adapted = tracker.adaptTo(corrected);
      result.adaptedOnFrames = done.run.corrected;
      const auto generalRows = trackThroughKeyframes(sequence.video, general, settings.tracker,
                                                     corrected, stage("general model"), cancel);
      const auto adaptedRows = trackThroughKeyframes(sequence.video, adapted, settings.tracker,
                                                     corrected, stage("adapted model"), cancel);
      result.generalError =
          uncorrectedError(truth, generalRows, corrected, scheme, &result.uncorrectedFrames);
      result.adaptedError = uncorrectedError(truth, adaptedRows, corrected, scheme, nullptr);
    }
    done.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.strategies.push_back(std::move(done));
  }
  return result;
}

std::string formatCorrectionBenchmark(const std::vector<SequenceBenchmark>& results,
                                      const AnnotatorSettings& settings) {
  std::ostringstream out;
  out << "A frame is right within " << settings.tolerance
      << " of the eye distance; a drag is a point farther than " << settings.dragTolerance
      << "; review-adapt adapts after every " << settings.adaptEvery << " corrections; at most "
      << settings.maxCorrections << " corrections a run.\n\n";
  out << "| sequence | frames | first track | wrong | strategy | corrected | drags | fallbacks | "
         "adaptations | re-tracks (frames) | left wrong | seconds |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  struct Total {
    AnnotatorStrategy strategy;
    int frames = 0, wrong = 0, corrected = 0, drags = 0, fallbacks = 0, adaptations = 0,
        retracks = 0, retracked = 0, left = 0, capped = 0;
    double seconds = 0.0;
  };
  std::vector<Total> totals;
  for (const SequenceBenchmark& sequence : results) {
    for (const StrategyResult& done : sequence.strategies) {
      const AnnotatorRun& run = done.run;
      out << "| " << sequence.sequence.label << " | " << sequence.frames << " | "
          << fixed(sequence.startError, 4) << " | " << run.wrongAtStart << " | "
          << annotatorStrategyName(run.strategy) << " | " << run.corrected
          << (run.capped ? " (capped)" : "") << " | " << run.drags << " | " << run.fallbacks
          << " | " << run.adaptations << " | " << run.retracks << " (" << run.retrackedFrames
          << ") | " << run.wrongAtEnd << " | " << fixed(done.seconds, 0) << " |\n";
      auto total = std::find_if(totals.begin(), totals.end(),
                                [&](const Total& t) { return t.strategy == run.strategy; });
      if (total == totals.end()) {
        totals.push_back(Total{run.strategy});
        total = totals.end() - 1;
      }
      total->frames += sequence.frames;
      total->wrong += run.wrongAtStart;
      total->corrected += run.corrected;
      total->drags += run.drags;
      total->fallbacks += run.fallbacks;
      total->adaptations += run.adaptations;
      total->retracks += run.retracks;
      total->retracked += run.retrackedFrames;
      total->left += run.wrongAtEnd;
      total->capped += run.capped ? 1 : 0;
      total->seconds += done.seconds;
    }
  }
  for (const Total& total : totals) {
    out << "| **total** | " << total.frames << " | | " << total.wrong << " | "
        << annotatorStrategyName(total.strategy) << " | " << total.corrected
        << (total.capped > 0 ? " (" + std::to_string(total.capped) + " capped)" : "") << " | "
        << total.drags << " | " << total.fallbacks << " | " << total.adaptations << " | "
        << total.retracks << " (" << total.retracked << ") | " << total.left << " | "
        << fixed(total.seconds, 0) << " |\n";
  }
  const auto corrections = [&](AnnotatorStrategy strategy) {
    for (const Total& total : totals) {
      if (total.strategy == strategy) return total.corrected;
    }
    return -1;
  };
  const int inOrder = corrections(AnnotatorStrategy::InOrder);
  const int adapt = corrections(AnnotatorStrategy::ReviewAdapt);
  if (inOrder > 0 && adapt >= 0) {
    out << "\nreview-adapt / in-order frames corrected: " << adapt << " / " << inOrder << " = "
        << fixed(static_cast<double>(adapt) / inOrder, 2) << '\n';
  }

  bool anyAdapted = false;
  for (const SequenceBenchmark& sequence : results) anyAdapted |= sequence.adaptedOnFrames > 0;
  if (anyAdapted) {
    out << "\nFrames review-adapt never corrected, tracked through its keyframes (mean error, eq. "
           "5.1):\n\n"
        << "| sequence | frames | adapted on | general model | adapted model | change |\n"
        << "|---|---|---|---|---|---|\n";
    for (const SequenceBenchmark& sequence : results) {
      if (sequence.adaptedOnFrames == 0) continue;
      const double change = sequence.adaptedError / sequence.generalError - 1.0;
      out << "| " << sequence.sequence.label << " | " << sequence.uncorrectedFrames << " | "
          << sequence.adaptedOnFrames << " | " << fixed(sequence.generalError, 4) << " | "
          << fixed(sequence.adaptedError, 4) << " | "
          << (std::isfinite(change) ? (change >= 0 ? "+" : "") + fixed(100.0 * change, 1) + "%"
                                    : std::string("-"))
          << " |\n";
    }
  }
  return out.str();
}

std::string correctionBenchmarkCsv(const std::vector<SequenceBenchmark>& results) {
  std::ostringstream out;
  out << "sequence,frames,scored,start_error,strategy,wrong_at_start,corrected,drags,fallbacks,"
         "adaptations,retracks,retracked_frames,wrong_at_end,capped,seconds,uncorrected_frames,"
         "general_error,adapted_error,corrected_frames\n";
  for (const SequenceBenchmark& sequence : results) {
    for (const StrategyResult& done : sequence.strategies) {
      const AnnotatorRun& run = done.run;
      const bool adapt = run.strategy == AnnotatorStrategy::ReviewAdapt;
      out << sequence.sequence.label << ',' << sequence.frames << ',' << run.scoredFrames << ','
          << csvNumber(sequence.startError, 6) << ',' << annotatorStrategyName(run.strategy) << ','
          << run.wrongAtStart << ',' << run.corrected << ',' << run.drags << ',' << run.fallbacks
          << ',' << run.adaptations << ',' << run.retracks << ',' << run.retrackedFrames << ','
          << run.wrongAtEnd << ',' << (run.capped ? 1 : 0) << ',' << csvNumber(done.seconds, 1)
          << ',' << (adapt ? std::to_string(sequence.uncorrectedFrames) : "") << ','
          << (adapt ? csvNumber(sequence.generalError, 6) : "") << ','
          << (adapt ? csvNumber(sequence.adaptedError, 6) : "") << ',';
      for (std::size_t i = 0; i < run.correctedFrames.size(); ++i) {
        out << (i > 0 ? " " : "") << run.correctedFrames[i];
      }
      out << '\n';
    }
  }
  return out.str();
}

}  // namespace clm3d
