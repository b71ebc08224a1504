// What `clm3d correction-bench` is asked for, described once as an option table (the files, the
// simulated annotator's rules, the review list's own table, `clm3d adapt`'s adaptation options and
// `clm3d track`'s tracker options), and its run: issue 29's correction benchmark
// (core/eval/detail/correction_benchmark.hpp) over one or more sequences, its tables as the
// command's output and, when asked, its CSV.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/command_report.hpp"
#include "core/common/option_table.hpp"
#include "core/common/progress.hpp"
#include "core/eval/simulated_annotator.hpp"
#include "core/track/adapt_request.hpp"
#include "core/track/tracker.hpp"

namespace clm3d {

struct CorrectionBenchRequest {
  std::filesystem::path model;
  std::vector<std::filesystem::path> videos, truths;  // paired, in order
  std::vector<std::string> labels;                    // empty, or one per video
  std::string strategies = "in-order,review,review-adapt";
  AnnotatorSettings annotator;
  AdaptRequest adapt;  // only its settings are read
  TrackerSettings tracker;
  std::filesystem::path csv;
  bool quiet = false;
};

// Every option of `clm3d correction-bench`, in its help's order.
const std::vector<Option<CorrectionBenchRequest>>& correctionBenchOptions();

// The strategies of a comma-separated list of their names, in its order; InputError naming a
// name that is none of them, or an empty list.
std::vector<AnnotatorStrategy> parseAnnotatorStrategies(const std::string& list);

// Runs the benchmark on every sequence; returns the tables (and a note of the CSV written).
// UsageError when the videos, truths and labels do not pair up.
CommandReport runCorrectionBench(const CorrectionBenchRequest& request,
                                 const ProgressCallback& progress = {},
                                 const CancelToken* cancel = nullptr);

}  // namespace clm3d
