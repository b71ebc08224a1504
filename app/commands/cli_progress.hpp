// Progress on stderr for the long commands (frames, track, batch, fit --images, train, synth,
// demo), one way for all of them instead of a lambda per command: a meter redrawn in place
// ("tracking: 42.0%") at most once a second, a line per finished item (the stage text of batch and
// image fits names the item), or a line at every tenth with the time so far and what is left
// ("train:  40% rendering, 95.5 s, ~143.1 s left").
// Core calls progress from worker threads (batch runs items in parallel), so every report is
// taken under a lock and printed whole. The object must outlive every use of callback(); its
// destructor closes an open meter line, so the command's next output starts on a line of its own.
#pragma once

#include <chrono>
#include <functional>
#include <iosfwd>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

#include "core/common/decile_progress.hpp"
#include "core/common/progress.hpp"

namespace clm3d::cli {

class CliProgress {
 public:
  enum class Style {
    Meter,  // "\rSTAGE: P%[ DETAIL]", redrawn at most once a second and at 100%
    Lines,  // "STAGE\n" for every report
    // "NAME: P% STAGE, T s, ~R s left\n" at every tenth reached (10, 20, ... 100; the estimate
    // left out at 100%), T the seconds since the object was made
    Tenths,
  };

  // quiet: print nothing (the commands' --quiet). `name` starts each Tenths line.
  CliProgress(Style style, bool quiet, std::ostream& out, std::string name = {});
  CliProgress(Style style, bool quiet);                    // on std::cerr
  CliProgress(Style style, bool quiet, std::string name);  // on std::cerr
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
  void printTenth(int percent, std::string_view stage);

  Style style_;
  bool quiet_;
  std::ostream& out_;
  std::string name_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::unique_ptr<DecileProgress> tenths_;  // Tenths
  std::function<std::string()> detail_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point lastDraw_{};
  bool drawn_ = false;     // a meter line is open
  bool drewDone_ = false;  // ... and it shows 100%
};

}  // namespace clm3d::cli
