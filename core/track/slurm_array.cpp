#include "core/track/detail/slurm_array.hpp"

#include <sys/wait.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <thread>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

struct CommandOutput {
  int exitCode = -1;
  std::string text;  // stdout and stderr
};

CommandOutput runShell(const std::string& commandLine) {
  CommandOutput result;
  FILE* pipe = popen((commandLine + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  std::size_t read = 0;
  while ((read = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    result.text.append(buffer.data(), read);
  }
  const int status = pclose(pipe);
  result.exitCode = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string trimmed(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ' || text.back() == '\r')) {
    text.pop_back();
  }
  return text;
}

}  // namespace

std::string shellQuote(std::string_view text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

std::string slurmArrayScript(const SlurmArrayJob& job) {
  std::ostringstream out;
  out << "#!/bin/bash\n"
      << "# Written by clm3d batch --slurm: task I of " << job.tasks
      << " runs shard I; `clm3d batch merge` joins their summaries.\n"
      << "#SBATCH --job-name=" << job.jobName << '\n'
      << "#SBATCH --array=1-" << job.tasks << '\n'
      << "#SBATCH --ntasks=1\n"
      << "#SBATCH --cpus-per-task=" << job.cpusPerTask << '\n'
      << "#SBATCH --chdir=" << job.workDir.string() << '\n'
      << "#SBATCH --output=" << (job.logDir / "task-%a.log").string() << '\n'
      << "exec";
  for (const std::string& word : job.command) out << ' ' << shellQuote(word);
  out << " --shard \"${SLURM_ARRAY_TASK_ID}/" << job.tasks << "\"\n";
  return out.str();
}

std::string submitSlurmJob(const std::filesystem::path& script,
                           const std::vector<std::string>& sbatchArgs) {
  std::string commandLine = "sbatch --parsable";
  for (const std::string& arg : sbatchArgs) commandLine += ' ' + shellQuote(arg);
  commandLine += ' ' + shellQuote(script.string());
  const CommandOutput result = runShell(commandLine);
  const std::string text = trimmed(result.text);
  // --parsable prints "ID" or "ID;CLUSTER"; warnings may come on lines before it.
  const std::string last =
      text.substr(text.find_last_of('\n') == std::string::npos ? 0 : text.find_last_of('\n') + 1);
  const std::string id = last.substr(0, last.find(';'));
  const bool numeric = !id.empty() && id.find_first_not_of("0123456789") == std::string::npos;
  if (result.exitCode != 0 || !numeric) {
    throw InputError("sbatch could not submit " + script.string() + " (exit " +
                     std::to_string(result.exitCode) +
                     "): " + (text.empty() ? std::string("no output; is Slurm installed?") : text));
  }
  return id;
}

void waitForSlurmJob(const std::string& jobId, double pollSeconds,
                     const std::function<void()>& tick, const CancelToken* cancel) {
  int failures = 0;
  const auto pause = std::chrono::duration<double>(pollSeconds);
  while (true) {
    if (cancel) cancel->throwIfCancelled();
    const CommandOutput result = runShell("squeue -h -j " + shellQuote(jobId) + " -o %i");
    if (tick) tick();
    if (result.exitCode == 0) {
      failures = 0;
      if (trimmed(result.text).empty()) return;
    } else if (result.text.find("Invalid job id") != std::string::npos) {
      return;  // finished and already purged from the controller
    } else if (++failures >= 10) {
      throw InputError("squeue cannot tell whether Slurm job " + jobId +
                       " is still running: " + trimmed(result.text));
    }
    std::this_thread::sleep_for(pause);
  }
}

}  // namespace clm3d
