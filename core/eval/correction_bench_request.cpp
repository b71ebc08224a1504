#include "core/eval/correction_bench_request.hpp"

#include <set>
#include <sstream>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/eval/detail/correction_benchmark.hpp"
#include "core/model/model_file.hpp"
#include "core/track/review_list.hpp"
#include "core/track/tracker_options.hpp"

namespace clm3d {
namespace correction_bench_request_detail {

using R = CorrectionBenchRequest;

void checkStrategies(std::string_view text) {
  parseAnnotatorStrategies(std::string(text));
}

std::vector<Option<R>> makeOptions() {
  std::vector<Option<R>> options{
      textOption<R>(requiredOption("model", "the general model (.clm3d)"), &R::model),
      textListOption<R>(requiredOption("video",
                                       "a sequence's video (repeat for each sequence; paired "
                                       "with the --truth of the same place)"),
                        &R::videos),
      textListOption<R>(requiredOption("truth",
                                       "its truth: a tracks or ground-truth CSV, one row per "
                                       "frame from 0 (its length is the sequence's); rows "
                                       "without points are not scored; 68 iBUG points are "
                                       "converted to thesis25"),
                        &R::truths),
      textListOption<R>(commandOption("label",
                                      "a name for each sequence in the tables (default: the "
                                      "video's file name)"),
                        &R::labels),
      textOption<R>(commandOption("strategies",
                                  "the annotator's strategies to run, comma-separated: in-order "
                                  "(the first wrong frame in frame order), review (the "
                                  "highest-ranked wrong frame of the review list), review-adapt "
                                  "(review, adapting the model every --adapt-every corrections)"),
                    &R::strategies, checkStrategies),
      realOption<R>(commandOption("tolerance",
                                  "a frame is right when its error (eq. 5.1) is at most this "
                                  "share of the true eye distance",
                                  0.001, 10),
                    [](R& r) -> double& { return r.annotator.tolerance; }),
      realOption<R>(commandOption("drag-tolerance",
                                  "a corrected frame's point farther than this share of the eye "
                                  "distance from its truth counts as one drag",
                                  0, 10),
                    [](R& r) -> double& { return r.annotator.dragTolerance; }),
      integerOption<R>(commandOption("adapt-every",
                                     "review-adapt: adapt the model after every this many "
                                     "corrections",
                                     1, 100000),
                       [](R& r) -> int& { return r.annotator.adaptEvery; }),
      integerOption<R>(commandOption("max-corrections",
                                     "a run stops after this many corrections (reported as "
                                     "capped)",
                                     0, 1000000),
                       [](R& r) -> int& { return r.annotator.maxCorrections; }),
      realOption<R>(commandOption("rejoin-tolerance",
                                  "the loop's re-track stops where it is within this share of "
                                  "the eye distance of the frame's previous points (the "
                                  "studio's rule; 0 never stops so)",
                                  0, 10),
                    [](R& r) -> double& { return r.annotator.retrack.rejoinTolerance; }),
      textOption<R>(commandOption("csv", "also write one row per sequence and strategy here"),
                    &R::csv),
      flagOption<R>(commandOption("quiet", "no progress on stderr"), &R::quiet),
  };
  // The review list's rules (`clm3d review`'s options).
  for (auto& option : nestedOptions<R>(
           reviewListOptions(), [](R& r) -> ReviewListSettings& { return r.annotator.review; })) {
    options.push_back(std::move(option));
  }
  // The adaptation's settings (`clm3d adapt`'s options, not its files; its --seed would clash
  // with the tracker's, so the adaptation keeps its default seed).
  const std::set<std::string> adaptSettings{"jitter", "prior", "refiner-prior", "min-regions",
                                            "threads"};
  std::vector<Option<AdaptRequest>> adapt;
  for (const auto& option : adaptRequestOptions()) {
    if (adaptSettings.count(option.name) > 0) adapt.push_back(option);
  }
  for (auto& option : nestedOptions<R>(adapt, &R::adapt)) options.push_back(std::move(option));
  // The tracker's (`clm3d track`'s options).
  std::vector<Option<TrackerSettings>> tracker;
  for (const TrackerOption* option : optionsFor(trackerOptions(), OptionCommand::Track)) {
    tracker.push_back(*option);
  }
  for (auto& option : nestedOptions<R>(tracker, &R::tracker)) options.push_back(std::move(option));
  return options;
}

}  // namespace correction_bench_request_detail

const std::vector<Option<CorrectionBenchRequest>>& correctionBenchOptions() {
  static const std::vector<Option<CorrectionBenchRequest>> table =
      correction_bench_request_detail::makeOptions();
  return table;
}

std::vector<AnnotatorStrategy> parseAnnotatorStrategies(const std::string& list) {
  std::vector<AnnotatorStrategy> strategies;
  std::stringstream items(list);
  std::string item;
  while (std::getline(items, item, ',')) {
    if (!item.empty()) strategies.push_back(annotatorStrategyByName(item));
  }
  if (strategies.empty()) throw InputError("--strategies: give at least one strategy");
  return strategies;
}

CommandReport runCorrectionBench(const CorrectionBenchRequest& args,
                                 const ProgressCallback& progress, const CancelToken* cancel) {
  if (args.videos.size() != args.truths.size()) {
    throw UsageError("--video/--truth", "give one --truth per --video (" +
                                            std::to_string(args.videos.size()) + " videos, " +
                                            std::to_string(args.truths.size()) + " truths)");
  }
  if (!args.labels.empty() && args.labels.size() != args.videos.size()) {
    throw UsageError("--label", "give one --label per --video, or none");
  }
  CorrectionBenchmarkSettings settings;
  try {
    settings.strategies = parseAnnotatorStrategies(args.strategies);
  } catch (const InputError& error) {
    throw UsageError("--strategies", error.what());
  }
  settings.annotator = args.annotator;
  settings.adapt = args.adapt.settings;
  settings.tracker = args.tracker;

  const ClmModel general = loadModel(args.model);
  std::vector<SequenceBenchmark> results;
  for (std::size_t i = 0; i < args.videos.size(); ++i) {
    BenchmarkSequence sequence;
    sequence.video = args.videos[i];
    sequence.truth = args.truths[i];
    sequence.label = args.labels.empty() ? sequence.video.stem().string() : args.labels[i];
    results.push_back(benchmarkSequence(general, args.model, sequence, settings, progress, cancel));
  }
  CommandReport report;
  for (const SequenceBenchmark& result : results) {
    if (!result.unreadable.empty()) report.warnings += "warning: " + result.unreadable + "\n";
  }
  report.text = formatCorrectionBenchmark(results, settings.annotator);
  if (!args.csv.empty()) {
    writeTextAtomically(args.csv, correctionBenchmarkCsv(results));
    report.notes = "csv: " + args.csv.string() + "\n";
  }
  return report;
}

}  // namespace clm3d
