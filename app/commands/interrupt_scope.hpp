// Ctrl-C for the long commands (train, fit --images, track, synth): while an InterruptScope lives,
// SIGINT cancels its token, so the core job stops at its next check and the command can say what
// it kept, instead of the process dying half-way through a write. The previous handler comes back
// when the scope ends, however it ends. One scope at a time (the commands run one job each).
#pragma once

#include <csignal>
#include <string>

#include "core/common/error.hpp"
#include "core/common/progress.hpp"

namespace clm3d::cli {

class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  CancelToken& token() { return token_; }
  // Restores the previous handler now (the rest of the command is not cancellable).
  void release();

 private:
  CancelToken token_;
  void (*previous_)(int) = nullptr;
  bool active_ = false;
};

// Runs job(token) inside an InterruptScope and returns what it returns; a job cancelled by Ctrl-C
// becomes Error(cancelledMessage) (e.g. "cancelled, no sequence written"), which the CLI prints.
template <typename Job>
auto runInterruptible(const std::string& cancelledMessage, Job job) {
  InterruptScope interrupt;
  try {
    return job(interrupt.token());
  } catch (const Cancelled&) {
    throw Error(cancelledMessage);
  }
}

}  // namespace clm3d::cli
