// Running a batch (batch_run) as a Slurm job array: the sbatch script whose task I of N runs
// `clm3d batch ... --shard I/N`, its submission with sbatch and the wait for it with squeue. Uses
// the cluster's own commands (sbatch, squeue on PATH, SLURM_CONF if set), nothing home-made in
// between: a lab's existing scheduler runs the shards, batch_run's merge joins their summaries.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/progress.hpp"

namespace clm3d {

// Text in single quotes for a POSIX shell (a quote inside becomes '\'').
std::string shellQuote(std::string_view text);

struct SlurmArrayJob {
  // The command every task runs, program first (absolute), without --shard: the script appends
  // --shard ${SLURM_ARRAY_TASK_ID}/tasks.
  std::vector<std::string> command;
  int tasks = 1;
  int cpusPerTask = 1;
  std::filesystem::path workDir;  // the tasks' working folder (relative paths in `command`)
  std::filesystem::path logDir;   // task-%a.log per task
  std::string jobName = "clm3d-batch";
};

// The sbatch script: #SBATCH lines for the array 1..tasks, the CPUs, the working folder and the
// logs, then the command.
std::string slurmArrayScript(const SlurmArrayJob& job);

// Runs `sbatch --parsable EXTRA... SCRIPT` and returns the job id. InputError with sbatch's output
// when it fails or prints no id (no Slurm here, a rejected option).
std::string submitSlurmJob(const std::filesystem::path& script,
                           const std::vector<std::string>& sbatchArgs);

// Polls `squeue -h -j ID` every `pollSeconds` until the job (every array task) has left the queue,
// calling `tick` after each poll. InputError when squeue keeps failing; Cancelled when cancelled
// (the job keeps running: it is the scheduler's, `scancel ID` stops it).
void waitForSlurmJob(const std::string& jobId, double pollSeconds,
                     const std::function<void()>& tick = {}, const CancelToken* cancel = nullptr);

}  // namespace clm3d
