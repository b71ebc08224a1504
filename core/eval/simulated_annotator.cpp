#include "core/eval/simulated_annotator.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>

#include "core/common/error.hpp"
#include "core/eval/landmark_error.hpp"

namespace clm3d {
namespace {

bool isWrong(const FrameError& frame, double tolerance) {
  return frame.normalised && !(frame.error <= tolerance);
}

// Every frame's error against the truth (evaluateSequence: one per truth row, frame order).
std::vector<FrameError> scoreFrames(const TrackTable& truth, const TrackTable& track,
                                    const Scheme& scheme) {
  return evaluateSequence(truth, track, scheme).frames;
}

// The first wrong frame in frame order that is not a keyframe; -1 when none.
int firstWrongFrame(const std::vector<FrameError>& frames, const std::vector<bool>& keyframe,
                    double tolerance) {
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (!keyframe[f] && isWrong(frames[f], tolerance)) return static_cast<int>(f);
  }
  return -1;
}

int countWrong(const std::vector<FrameError>& frames, double tolerance) {
  int wrong = 0;
  for (const FrameError& frame : frames) wrong += isWrong(frame, tolerance) ? 1 : 0;
  return wrong;
}

// The highest-ranked frame of the review list that is wrong; -1 when the list offers none.
int firstWrongListed(const GroundTruthSet& set, const std::vector<FrameError>& frames,
                     const Scheme& scheme, const AnnotatorSettings& settings) {
  const std::vector<ReviewItem> items =
      rankFramesForReview(set.table, set.keyframe, scheme.normalisationPair(), settings.review);
  for (const ReviewItem& item : items) {
    const auto f = static_cast<std::size_t>(item.frame);
    if (f < frames.size() && !set.keyframe[f] && isWrong(frames[f], settings.tolerance)) {
      return item.frame;
    }
  }
  return -1;
}

int dragsToCorrect(const FrameError& frame, double dragTolerance) {
  int drags = 0;
  for (std::size_t k = 0; k < frame.truePoints.size(); ++k) {
    if (frame.truePoints[k] && !(frame.pointErrors[k] <= dragTolerance)) ++drags;
  }
  return drags;
}

// The truth set as the annotator starts it: the track's rows of frames 0..n-1, no keyframe.
GroundTruthSet startingSet(const TrackTable& truth, const TrackTable& track) {
  const int count = static_cast<int>(truth.rows.size());
  for (std::size_t f = 0; f < truth.rows.size(); ++f) {
    if (truth.rows[f].frame != static_cast<int>(f)) {
      throw InputError("correction benchmark: the truth's row " + std::to_string(f) + " is frame " +
                       std::to_string(truth.rows[f].frame) +
                       " (it needs one row per frame, in order)");
    }
  }
  if (track.landmarkCount != truth.landmarkCount) {
    throw InputError("correction benchmark: the track has " + std::to_string(track.landmarkCount) +
                     " landmarks, the truth " + std::to_string(truth.landmarkCount));
  }
  TrackTable first = track;
  std::erase_if(first.rows, [count](const TrackRow& row) { return row.frame >= count; });
  return GroundTruthSet::fromTrack(first, count);
}

}  // namespace

const char* annotatorStrategyName(AnnotatorStrategy strategy) {
  switch (strategy) {
    case AnnotatorStrategy::InOrder:
      return "in-order";
    case AnnotatorStrategy::Review:
      return "review";
    case AnnotatorStrategy::ReviewAdapt:
      return "review-adapt";
  }
  return "?";
}

AnnotatorStrategy annotatorStrategyByName(const std::string& name) {
  for (const AnnotatorStrategy strategy :
       {AnnotatorStrategy::InOrder, AnnotatorStrategy::Review, AnnotatorStrategy::ReviewAdapt}) {
    if (name == annotatorStrategyName(strategy)) return strategy;
  }
  throw InputError("unknown annotator strategy \"" + name +
                   "\" (in-order, review or review-adapt)");
}

void AnnotatorSettings::validate() const {
  if (!(tolerance > 0.0)) throw InputError("annotator: the tolerance must be above 0");
  if (!(dragTolerance >= 0.0)) throw InputError("annotator: the drag tolerance must be >= 0");
  if (adaptEvery < 1) throw InputError("annotator: adapt-every must be at least 1");
  if (maxCorrections < 0) throw InputError("annotator: max-corrections must be >= 0");
}

AnnotatorRun simulateAnnotator(AnnotatorStrategy strategy, const TrackTable& truth,
                               const TrackTable& track, const Scheme& scheme,
                               AnnotatorTracker& tracker, const AnnotatorSettings& settings,
                               const ProgressCallback& progress, const CancelToken* cancel) {
  settings.validate();
  AnnotatorRun run;
  run.strategy = strategy;
  GroundTruthSet set = startingSet(truth, track);
  std::vector<FrameError> frames = scoreFrames(truth, set.table, scheme);
  for (const FrameError& frame : frames) run.scoredFrames += frame.normalised ? 1 : 0;
  run.wrongAtStart = countWrong(frames, settings.tolerance);

  const auto report = [&](int wrongNow) {
    if (!progress) return;
    const double done =
        run.wrongAtStart > 0 ? 1.0 - static_cast<double>(wrongNow) / run.wrongAtStart : 1.0;
    progress(std::max(0.0, done), std::string(annotatorStrategyName(strategy)) + ": " +
                                      std::to_string(run.corrected) + " corrected, " +
                                      std::to_string(wrongNow) + " wrong");
  };
  for (;;) {
    if (cancel != nullptr) cancel->throwIfCancelled();
    const int firstWrong = firstWrongFrame(frames, set.keyframe, settings.tolerance);
    if (firstWrong < 0) break;
    if (run.corrected >= settings.maxCorrections) {
      run.capped = true;
      break;
    }
    int pick = firstWrong;
    if (strategy != AnnotatorStrategy::InOrder) {
      pick = firstWrongListed(set, frames, scheme, settings);
      if (pick < 0) {
        pick = firstWrong;
        ++run.fallbacks;
      }
    }
    const auto picked = static_cast<std::size_t>(pick);
    run.drags += dragsToCorrect(frames[picked], settings.dragTolerance);
    const Eigen::Matrix2Xd points = truth.rows[picked].points;
    set.setKeyframe(pick, points);
    ++run.corrected;
    run.correctedFrames.push_back(pick);

    // The studio's loop: re-track forward from the corrected frame, by its rules.
    const std::vector<int> span = retrackFrames(set.keyframe, pick, RetrackDirection::Forward);
    if (!span.empty()) {
      const SpanRetrack retrack =
          tracker.retrack(pick, points, span, set.table.rows, settings.retrack);
      int kept = 0;
      for (std::size_t i = 0; i < retrack.rows.size() && i < span.size(); ++i) {
        if (retrack.rows[i].frame != span[i]) break;
        set.table.rows[static_cast<std::size_t>(span[i])] = retrack.rows[i];
        ++kept;
      }
      if (kept > 0) {
        ++run.retracks;
        run.retrackedFrames += kept;
      }
    }

    if (strategy == AnnotatorStrategy::ReviewAdapt && run.corrected % settings.adaptEvery == 0) {
      const std::vector<TrackRow> rows = tracker.adapt(set);
      for (const TrackRow& row : rows) {
        const auto f = static_cast<std::size_t>(row.frame);
        if (row.frame >= 0 && f < set.keyframe.size() && !set.keyframe[f]) set.table.rows[f] = row;
      }
      ++run.adaptations;
    }
    frames = scoreFrames(truth, set.table, scheme);
    report(countWrong(frames, settings.tolerance));
  }
  run.wrongAtEnd = countWrong(frames, settings.tolerance);
  run.result = std::move(set);
  return run;
}

}  // namespace clm3d
