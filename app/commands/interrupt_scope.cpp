#include "app/commands/interrupt_scope.hpp"

#include <atomic>

namespace clm3d::cli {
namespace {

std::atomic<CancelToken*> gToken{nullptr};

extern "C" void onInterrupt(int) {
  if (CancelToken* token = gToken.load()) token->cancel();
}

}  // namespace

InterruptScope::InterruptScope() {
  gToken = &token_;
  previous_ = std::signal(SIGINT, onInterrupt);
  active_ = true;
}

InterruptScope::~InterruptScope() {
  release();
}

void InterruptScope::release() {
  if (!active_) return;
  std::signal(SIGINT, previous_);
  gToken = nullptr;
  active_ = false;
}

}  // namespace clm3d::cli
