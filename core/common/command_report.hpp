// What a command's run in core (a *_request: core/eval/eval_request, core/profile/synth_request,
// ...) gives the CLI to print: warnings for stderr, the text for stdout and notes (where files
// went), which go to stderr when stdout must hold only a JSON document (--json); and a failure
// that makes the command exit 1 after all of it is printed (e.g. a batch in which some items
// failed). Core never prints; the CLI prints this as is (app/commands/option_cli: printOutput).
#pragma once

#include <functional>
#include <string>
#include <utility>

#include "core/common/progress.hpp"

namespace clm3d {

struct CommandReport {
  CommandReport() = default;
  CommandReport(std::string printed) : text(std::move(printed)) {}  // NOLINT: a plain text

  std::string warnings;  // stderr, first
  std::string text;      // stdout
  std::string notes;     // after the text
  bool notesToStderr = false;
  std::string failure;  // when not empty: printed last as the command's error (exit 1)
};

// How a long run in core (e.g. core/demo/demo_run) speaks while it goes: text for stdout as each
// stage ends, notes for stderr, and a progress callback for each named stage (asked for as the
// stage starts; what it returns must stay usable until the run ends). Empty members are quiet.
struct RunReporter {
  std::function<void(const std::string&)> print;
  std::function<void(const std::string&)> note;
  std::function<ProgressCallback(const std::string& stage)> progress;

  void say(const std::string& text) const {
    if (print) print(text);
  }
  void tell(const std::string& text) const {
    if (note) note(text);
  }
  ProgressCallback stage(const std::string& name) const {
    return progress ? progress(name) : ProgressCallback{};
  }
};

}  // namespace clm3d
