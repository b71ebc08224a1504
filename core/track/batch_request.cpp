#include "core/track/batch_request.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <sstream>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/image_list.hpp"
#include "core/model/model_file.hpp"
#include "core/track/batch_run.hpp"
#include "core/track/detail/slurm_array.hpp"

namespace clm3d {
namespace batch_request_detail {

namespace fs = std::filesystem;
using R = BatchRequest;

std::vector<Option<R>> makeOptions() {
  const auto path = [](const char* name, const char* help, fs::path R::*field) {
    return textOption<R>(commandOption(name, help), field);
  };
  const auto flag = [](const char* name, const char* help, bool R::*field) {
    return flagOption<R>(commandOption(name, help), field);
  };
  return {
      path("model", "trained model (.clm3d)", &R::model),
      path("input",
           "a folder (every image and video in it, sorted) or a job file with one image or video "
           "path per line (relative to the file's folder; # comments)",
           &R::input),
      path("out-dir",
           "outputs: STEM.pts per image, STEM.csv per video (docs/tracks-csv.md), status/ and "
           "summary.csv",
           &R::outDir),
      path("init-dir",
           "start each image from STEM.pts, .ljson or .csv in this folder instead of the face "
           "detector",
           &R::initDir),
      integerOption<R>(commandOption("threads", "worker threads (0: one per core)", 0, 256),
                       &R::threads),
      textOption<R>(commandOption("shard",
                                  "run only shard I of N (items I, I+N, I+2N, ...; 1 <= I <= N) "
                                  "and write summary-I-of-N.csv; `clm3d batch merge` joins the N "
                                  "summaries"),
                    &R::shard),
      flag("redo", "run finished items again", &R::redo),
      flag("quiet", "no progress on stderr", &R::quiet),
      flag("keep-rejected",
           "images: write the points of a fit that the model's point check rejects (by default "
           "they are not written)",
           &R::keepRejected),
      integerOption<R>(commandOption("slurm",
                                     "submit a Slurm job array of N tasks (sbatch), one shard "
                                     "each, wait for it and merge the summaries",
                                     1, 100000),
                       &R::slurmTasks),
      textListOption<R>(commandOption("sbatch-arg",
                                      "with --slurm: an extra sbatch option, e.g. "
                                      "--sbatch-arg=--partition=gpu (repeat for more)"),
                        &R::sbatchArgs),
      flag("no-wait", "with --slurm: submit and return; merge later with `clm3d batch merge`",
           &R::noWait),
  };
}

BatchJob makeJob(const R& args) {
  BatchJob job;
  job.inputs = listImagesAndVideos(args.input);
  job.outDir = args.outDir;
  job.initDir = args.initDir;
  job.threads = args.threads;
  job.redo = args.redo;
  if (!args.shard.empty()) {
    const auto shard = parseBatchShard(args.shard);
    if (!shard) throw UsageError("--shard", "expected I/N with 1 <= I <= N, e.g. 2/8");
    job.shard = *shard;
  }
  if (!job.initDir.empty() && !fs::is_directory(job.initDir)) {
    throwInputError(job.initDir, "no such folder (--init-dir)");
  }
  return job;
}

BatchSettings makeSettings(const R& args) {
  BatchSettings settings = batchSettings(args.tracker);
  settings.image.keepRejected = args.keepRejected;
  return settings;
}

// The counts line, and the failure when any item failed.
void addCounts(CommandReport& output, int items, int ok, int rejected, int noFace, int errors,
               const fs::path& summary) {
  output.text += std::to_string(ok) + " of " + std::to_string(items) + " items ok, " +
                 std::to_string(rejected) + " rejected by the point check, " +
                 std::to_string(noFace) + " without a face, " + std::to_string(errors) +
                 " failed (summary: " + summary.string() + ")\n";
  if (errors > 0) {
    output.failure = std::to_string(errors) + " of " + std::to_string(items) +
                     " items failed (see " + summary.string() + ")";
  }
}

CommandReport runLocal(const R& args, const RunReporter& reporter, const CancelToken* cancel) {
  const BatchJob job = makeJob(args);
  const BatchSettings settings = makeSettings(args);
  if (!job.redo) checkBatchOptions(job.outDir, batchOptions(job, settings));  // before the load
  const ClmModel model = loadModel(args.model);
  const auto begin = std::chrono::steady_clock::now();
  const BatchRunSummary summary = runBatch(model, job, settings, reporter.stage("batch"), cancel);
  CommandReport output;
  for (const BatchRow& row : summary.rows) {
    if (row.status == ImageFitStatus::Error) output.warnings += "error: " + row.error + '\n';
    // A video tracked with unreadable frames (unreadableFramesWarning).
    if (row.status == ImageFitStatus::Ok && !row.error.empty()) {
      output.warnings += "warning: " + row.error + '\n';
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  const int ran = static_cast<int>(summary.rows.size()) - summary.skipped;
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << "batch"
       << (job.shard.whole() ? std::string()
                             : " shard " + std::to_string(job.shard.index) + "/" +
                                   std::to_string(job.shard.count))
       << ": " << ran << " items run in " << seconds << " s ("
       << (seconds > 0.0 ? 60.0 * ran / seconds : 0.0) << " items/min), " << summary.skipped
       << " finished before\n";
  output.text = text.str();
  addCounts(output, static_cast<int>(summary.rows.size()), summary.ok, summary.rejected,
            summary.noFace, summary.errors, summary.summaryCsv);
  return output;
}

CommandReport runSlurm(const R& args, const std::vector<std::string>& taskCommand,
                       const RunReporter& reporter, const CancelToken* cancel) {
  if (!args.shard.empty()) throw UsageError("--shard", "--slurm picks the shards itself");
  const BatchJob job = makeJob(args);  // bad input is reported here, not in every task's log
  if (!job.redo) checkBatchOptions(job.outDir, batchOptions(job, makeSettings(args)));
  const int tasks = std::min<int>(args.slurmTasks, static_cast<int>(job.inputs.size()));
  std::error_code error;
  const fs::path slurmDir = fs::absolute(args.outDir) / "slurm";
  fs::create_directories(slurmDir, error);
  if (error) throwInputError(slurmDir, "cannot create the folder: " + error.message());
  // Shard summaries of an earlier submission would be merged with this one's.
  for (const fs::directory_entry& entry : fs::directory_iterator(args.outDir, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("summary-", 0) == 0 && name.find("-of-") != std::string::npos) {
      fs::remove(entry.path(), error);
    }
  }
  SlurmArrayJob array;
  array.command = taskCommand;
  array.tasks = tasks;
  array.cpusPerTask = std::max(1, args.threads);
  array.workDir = fs::current_path();
  array.logDir = slurmDir;
  const fs::path script = slurmDir / "batch-array.sh";
  writeTextAtomically(script, slurmArrayScript(array));
  const std::string jobId = submitSlurmJob(script, args.sbatchArgs);
  reporter.say("submitted Slurm job " + jobId + ": " + std::to_string(tasks) + " tasks over " +
               std::to_string(job.inputs.size()) + " items (script " + script.string() + ", logs " +
               (slurmDir / "task-N.log").string() + ")\n");
  if (args.noWait) {
    return CommandReport("when it has finished: clm3d batch merge --out-dir " +
                         args.outDir.string() + '\n');
  }
  int reported = -1;
  const auto tick = [&] {
    int finished = 0;
    for (int index = 1; index <= tasks; ++index) {
      finished += fs::exists(batchSummaryPath(args.outDir, BatchShard{index, tasks})) ? 1 : 0;
    }
    if (finished != reported && !args.quiet) {
      reporter.tell("slurm job " + jobId + ": " + std::to_string(finished) + "/" +
                    std::to_string(tasks) + " tasks done\n");
    }
    reported = finished;
  };
  try {
    waitForSlurmJob(jobId, 1.0, tick, cancel);
  } catch (const Cancelled&) {
    throw InputError("stopped waiting; Slurm job " + jobId + " goes on (scancel " + jobId +
                     " stops it; clm3d batch merge --out-dir " + args.outDir.string() +
                     " when it has finished)");
  }
  BatchMergeSummary merged;
  try {
    merged = mergeBatchShards(args.outDir);
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + "; the task logs are in " + slurmDir.string());
  }
  CommandReport output;
  addCounts(output, static_cast<int>(merged.rows.size()), merged.ok, merged.rejected, merged.noFace,
            merged.errors, merged.summaryCsv);
  return output;
}

}  // namespace batch_request_detail

const std::vector<Option<BatchRequest>>& batchRequestOptions() {
  static const std::vector<Option<BatchRequest>> table = batch_request_detail::makeOptions();
  return table;
}

const std::vector<std::string>& batchSubmitOnlyOptions() {
  static const std::vector<std::string> names{"--slurm", "--sbatch-arg", "--no-wait", "--shard"};
  return names;
}

CommandReport runBatchRequest(const BatchRequest& args, const std::vector<std::string>& taskCommand,
                              const RunReporter& reporter, const CancelToken* cancel) {
  if (args.model.empty() || args.input.empty() || args.outDir.empty()) {
    throw UsageError("--model/--input/--out-dir",
                     "clm3d batch needs --model M --input DIR|LIST --out-dir OUT");
  }
  if (args.slurmTasks == 0 && (!args.sbatchArgs.empty() || args.noWait)) {
    throw UsageError("--sbatch-arg/--no-wait", "go with --slurm N");
  }
  if (args.slurmTasks > 0) {
    return batch_request_detail::runSlurm(args, taskCommand, reporter, cancel);
  }
  return batch_request_detail::runLocal(args, reporter, cancel);
}

CommandReport mergeBatchOutputs(const std::filesystem::path& outDir) {
  const BatchMergeSummary merged = mergeBatchShards(outDir);
  CommandReport output("merged " + std::to_string(merged.shards) + " shard summaries\n");
  batch_request_detail::addCounts(output, static_cast<int>(merged.rows.size()), merged.ok,
                                  merged.rejected, merged.noFace, merged.errors, merged.summaryCsv);
  return output;
}

}  // namespace clm3d
