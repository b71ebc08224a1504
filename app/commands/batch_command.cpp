// clm3d batch: many images and videos with the model loaded once (core/track/batch_run): a folder
// or a job file in, OUT/STEM.pts per image and OUT/STEM.csv per video out, on --threads workers,
// resumable (a rerun skips finished items), --shard I/N for one of N processes, --slurm N to run
// the N shards as a Slurm job array and merge them; `clm3d batch merge` joins shard summaries.
// Exit 1 when any item failed (after every item and the summary). Ctrl-C stops after the running
// items, keeping what is finished.
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <set>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/fit_options.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/image_list.hpp"
#include "core/model/model_file.hpp"
#include "core/track/batch_run.hpp"
#include "core/track/slurm_array.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct BatchArgs {
  fs::path model, input, outDir, initDir;
  int threads = 1;
  std::string shard;
  bool redo = false;
  bool quiet = false;
  bool keepRejected = false;
  int slurmTasks = 0;
  std::vector<std::string> sbatchArgs;
  bool noWait = false;
  FitOptions fit;
  CLI::App* command = nullptr;
};

// The options of the Slurm submission itself, left out of the tasks' command line.
const std::set<std::string> kSubmitOnly{"--slurm", "--sbatch-arg", "--no-wait", "--shard"};

// The `clm3d batch` command line each array task runs: this program and every option given here
// but the submission's own.
std::vector<std::string> taskCommand(const CLI::App& command) {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) throw Error("cannot find the clm3d program (/proc/self/exe): " + error.message());
  std::vector<std::string> words{self.string(), "batch"};
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0 || option->get_lnames().empty()) continue;  // not given, positional
    const std::string name = "--" + option->get_lnames().front();
    if (kSubmitOnly.count(name) > 0) continue;
    if (option->get_expected_min() == 0) {  // a flag
      words.push_back(name);
      continue;
    }
    for (const std::string& value : option->results()) {
      words.push_back(name);
      words.push_back(value);
    }
  }
  return words;
}

BatchJob makeJob(const BatchArgs& args) {
  BatchJob job;
  job.inputs = listImagesAndVideos(args.input);
  job.outDir = args.outDir;
  job.initDir = args.initDir;
  job.threads = args.threads;
  job.redo = args.redo;
  if (!args.shard.empty()) {
    const auto shard = parseBatchShard(args.shard);
    if (!shard) throw CLI::ValidationError("--shard", "expected I/N with 1 <= I <= N, e.g. 2/8");
    job.shard = *shard;
  }
  if (!job.initDir.empty() && !fs::is_directory(job.initDir)) {
    throwInputError(job.initDir, "no such folder (--init-dir)");
  }
  return job;
}

void reportCounts(int items, int ok, int rejected, int noFace, int errors,
                  const fs::path& summary) {
  std::cout << ok << " of " << items << " items ok, " << rejected
            << " rejected by the point check, " << noFace << " without a face, " << errors
            << " failed (summary: " << summary.string() << ")\n";
  if (errors > 0) {
    throw InputError(std::to_string(errors) + " of " + std::to_string(items) +
                     " items failed (see " + summary.string() + ")");
  }
}

BatchSettings makeSettings(const BatchArgs& args) {
  BatchSettings settings = batchSettings(args.fit.tracker, args.fit.fovDeg);
  settings.image.keepRejected = args.keepRejected;
  return settings;
}

void runLocal(const BatchArgs& args) {
  const BatchJob job = makeJob(args);
  const BatchSettings settings = makeSettings(args);
  if (!job.redo) checkBatchOptions(job.outDir, batchOptions(job, settings));  // before the load
  const ClmModel model = loadModel(args.model);
  InterruptScope interrupt;
  CliProgress progress(CliProgress::Style::Lines, args.quiet);
  const auto begin = std::chrono::steady_clock::now();
  const BatchRunSummary summary =
      runBatch(model, job, settings, progress.callback(), &interrupt.token());
  interrupt.release();
  for (const BatchRow& row : summary.rows) {
    if (row.status == ImageFitStatus::Error) std::cerr << "error: " << row.error << '\n';
    // A video tracked with unreadable frames (unreadableFramesWarning).
    if (row.status == ImageFitStatus::Ok && !row.error.empty()) {
      std::cerr << "warning: " << row.error << '\n';
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  const int ran = static_cast<int>(summary.rows.size()) - summary.skipped;
  std::cout << std::fixed << std::setprecision(1) << "batch"
            << (job.shard.whole() ? std::string()
                                  : " shard " + std::to_string(job.shard.index) + "/" +
                                        std::to_string(job.shard.count))
            << ": " << ran << " items run in " << seconds << " s ("
            << (seconds > 0.0 ? 60.0 * ran / seconds : 0.0) << " items/min), " << summary.skipped
            << " finished before\n";
  reportCounts(static_cast<int>(summary.rows.size()), summary.ok, summary.rejected, summary.noFace,
               summary.errors, summary.summaryCsv);
}

void runSlurm(const BatchArgs& args) {
  if (!args.shard.empty()) throw CLI::ValidationError("--shard", "--slurm picks the shards itself");
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
  array.command = taskCommand(*args.command);
  array.tasks = tasks;
  array.cpusPerTask = std::max(1, args.threads);
  array.workDir = fs::current_path();
  array.logDir = slurmDir;
  const fs::path script = slurmDir / "batch-array.sh";
  writeTextAtomically(script, slurmArrayScript(array));
  const std::string jobId = submitSlurmJob(script, args.sbatchArgs);
  std::cout << "submitted Slurm job " << jobId << ": " << tasks << " tasks over "
            << job.inputs.size() << " items (script " << script.string() << ", logs "
            << (slurmDir / "task-N.log").string() << ")\n"
            << std::flush;
  if (args.noWait) {
    std::cout << "when it has finished: clm3d batch merge --out-dir " << args.outDir.string()
              << '\n';
    return;
  }
  InterruptScope interrupt;
  int reported = -1;
  const auto tick = [&] {
    int finished = 0;
    for (int index = 1; index <= tasks; ++index) {
      finished += fs::exists(batchSummaryPath(args.outDir, BatchShard{index, tasks})) ? 1 : 0;
    }
    if (finished != reported && !args.quiet) {
      std::cerr << "slurm job " << jobId << ": " << finished << "/" << tasks << " tasks done\n";
    }
    reported = finished;
  };
  try {
    waitForSlurmJob(jobId, 1.0, tick, &interrupt.token());
  } catch (const Cancelled&) {
    throw InputError("stopped waiting; Slurm job " + jobId + " goes on (scancel " + jobId +
                     " stops it; clm3d batch merge --out-dir " + args.outDir.string() +
                     " when it has finished)");
  }
  interrupt.release();
  BatchMergeSummary merged;
  try {
    merged = mergeBatchShards(args.outDir);
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + "; the task logs are in " + slurmDir.string());
  }
  reportCounts(static_cast<int>(merged.rows.size()), merged.ok, merged.rejected, merged.noFace,
               merged.errors, merged.summaryCsv);
}

void runMerge(const fs::path& outDir) {
  const BatchMergeSummary merged = mergeBatchShards(outDir);
  std::cout << "merged " << merged.shards << " shard summaries\n";
  reportCounts(static_cast<int>(merged.rows.size()), merged.ok, merged.rejected, merged.noFace,
               merged.errors, merged.summaryCsv);
}

}  // namespace

void addBatchCommand(CLI::App& root) {
  auto args = std::make_shared<BatchArgs>();
  CLI::App* command = root.add_subcommand(
      "batch",
      "fit many images and track many videos with the model loaded once: resumable, sharded, on "
      "Slurm (docs/batch.md)");
  args->command = command;
  command->add_option("--model", args->model, "trained model (.clm3d)");
  command->add_option("--input", args->input,
                      "a folder (every image and video in it, sorted) or a job file with one "
                      "image or video path per line (relative to the file's folder; # comments)");
  command->add_option("--out-dir", args->outDir,
                      "outputs: STEM.pts per image, STEM.csv per video (docs/tracks-csv.md), "
                      "status/ and summary.csv");
  command->add_option("--init-dir", args->initDir,
                      "start each image from STEM.pts, .ljson or .csv in this folder instead of "
                      "the face detector");
  command->add_option("--threads", args->threads, "worker threads (0: one per core)")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));
  command->add_option("--shard", args->shard,
                      "run only shard I of N (items I, I+N, I+2N, ...; 1 <= I <= N) and write "
                      "summary-I-of-N.csv; `clm3d batch merge` joins the N summaries");
  command->add_flag("--redo", args->redo, "run finished items again");
  command->add_flag("--quiet", args->quiet, "no progress on stderr");
  command->add_flag("--keep-rejected", args->keepRejected,
                    "images: write the points of a fit that the model's point check rejects (by "
                    "default they are not written)");
  command
      ->add_option("--slurm", args->slurmTasks,
                   "submit a Slurm job array of N tasks (sbatch), one shard each, wait for it "
                   "and merge the summaries")
      ->check(CLI::Range(1, 100000));
  command->add_option("--sbatch-arg", args->sbatchArgs,
                      "with --slurm: an extra sbatch option, e.g. --sbatch-arg=--partition=gpu "
                      "(repeat for more)");
  command->add_flag("--no-wait", args->noWait,
                    "with --slurm: submit and return; merge later with `clm3d batch merge`");
  // The options of `clm3d fit` and of `clm3d track` (core/track/tracker_options): images are
  // fitted, videos tracked; recorded in OUT/options.txt, and a rerun with others is refused.
  addFitOptions(*command, args->fit, OptionCommand::Batch);

  auto mergeDir = std::make_shared<fs::path>();
  CLI::App* merge = command->add_subcommand(
      "merge", "join the shard summaries OUT/summary-I-of-N.csv into OUT/summary.csv");
  merge->add_option("--out-dir", *mergeDir, "the batch's output folder")->required();
  merge->callback([mergeDir] { runMerge(*mergeDir); });
  command->require_subcommand(0, 1);

  command->callback([args, merge] {
    if (merge->parsed()) return;
    if (args->model.empty() || args->input.empty() || args->outDir.empty()) {
      throw CLI::ValidationError("--model/--input/--out-dir",
                                 "clm3d batch needs --model M --input DIR|LIST --out-dir OUT");
    }
    if (args->slurmTasks == 0 && (!args->sbatchArgs.empty() || args->noWait)) {
      throw CLI::ValidationError("--sbatch-arg/--no-wait", "go with --slurm N");
    }
    if (args->slurmTasks > 0) {
      runSlurm(*args);
    } else {
      runLocal(*args);
    }
  });
}

}  // namespace clm3d::cli
