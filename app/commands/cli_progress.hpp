// Progress on stderr for the long commands (frames, track, batch, fit --images), one way for all of
// them instead of a lambda per command: a meter redrawn in place ("tracking: 42.0%") at most once a
// second, or a line per finished item (the stage text of batch and image fits names the item).
// Core calls progress from worker threads (batch runs items in parallel), so every report is
// taken under a lock and printed whole. The object must outlive every use of callback(); its
// destructor closes an open meter line, so the command's next output starts on a line of its own.
#pragma once

#include <chrono>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <string>
#include <string_view>

#include "core/common/progress.hpp"

namespace clm3d::cli {

class CliProgress {
 public:
  enum class Style {
    Meter,  // "\rSTAGE: P%[ DETAIL]", redrawn at most once a second and at 100%
    Lines,  // "STAGE\n" for every report
  };

  // quiet: print nothing (the commands' --quiet).
  CliProgress(Style style, bool quiet, std::ostream& out);
  CliProgress(Style style, bool quiet);  // on std::cerr
  ~CliProgress();
  CliProgress(const CliProgress&) = delete;
  CliProgress& operator=(const CliProgress&) = delete;

  // Meter only: text after the percentage (e.g. "(120 frames)"), asked for under the lock at
  // each redraw; it must be safe to call from the thread that reports.
  void setDetail(std::function<std::string()> detail);

  void operator()(double fraction, std::string_view stage);
  // A callback for core functions; `this` must outlive its use.
  ProgressCallback callback();
  // Ends an open meter line with a line break (the destructor does it too).
  void finish();

 private:
  Style style_;
  bool quiet_;
  std::ostream& out_;
  std::function<std::string()> detail_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point lastDraw_{};
  bool drawn_ = false;     // a meter line is open
  bool drewDone_ = false;  // ... and it shows 100%
};

}  // namespace clm3d::cli
