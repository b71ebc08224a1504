// What `clm3d batch` is asked for besides the tracker table's Batch options (core/track/
// tracker_options, which the CLI adds itself): the job, its shard and its Slurm submission,
// described once as an option table, and its runs: the job run here (core/track/batch_run), or
// submitted as a Slurm job array (core/track/slurm_array), waited for and merged; and the merge of
// shard summaries (`clm3d batch merge`). The outputs' failure says why the command exits 1 (items
// that failed), after the counts are printed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/command_report.hpp"
#include "core/common/option_table.hpp"
#include "core/track/tracker_options.hpp"

namespace clm3d {

struct BatchRequest {
  std::filesystem::path model, input, outDir, initDir;
  int threads = 1;
  std::string shard;  // "I/N"
  bool redo = false;
  bool quiet = false;
  bool keepRejected = false;
  int slurmTasks = 0;  // --slurm N
  std::vector<std::string> sbatchArgs;
  bool noWait = false;
  // From the tracker table's Batch options and --fov (verticalFovDeg), which the CLI adds beside
  // these.
  TrackerSettings tracker;
};

// The options of `clm3d batch` that are not the tracker table's, in its help's order.
const std::vector<Option<BatchRequest>>& batchRequestOptions();

// The options of the Slurm submission itself, which its tasks' command line leaves out.
const std::vector<std::string>& batchSubmitOnlyOptions();

// Runs the request: here (progress: reporter.stage("batch"), each finished item), or with
// --slurm as a job array whose tasks run `taskCommand` (this program's `batch` with the options
// given but the submission's own), saying the submission through the reporter, its tasks done on
// its notes unless --quiet, then merging. UsageError for options that do not go together.
CommandReport runBatchRequest(const BatchRequest& request,
                              const std::vector<std::string>& taskCommand,
                              const RunReporter& reporter, const CancelToken* cancel);

// `clm3d batch merge`: the shard summaries of outDir joined into its summary.csv.
CommandReport mergeBatchOutputs(const std::filesystem::path& outDir);

}  // namespace clm3d
