// What `clm3d demo` is asked for, described once as an option table (the CLI builds the command's
// options from it), and its run: the stages of core/demo/demo_pipeline in turn (procedural heads,
// training-view renders, training, the held-out test sequence, tracking, the evaluation), the
// folder saved as a studio project, and with --real the real-face model trained and franck.mp4
// tracked into it. It speaks through a RunReporter as each stage ends.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/command_report.hpp"
#include "core/common/option_table.hpp"

namespace clm3d {

struct DemoRequest {
  std::filesystem::path out = "demo-out";
  int heads = 8;
  int size = 192;
  int threads = 0;
  int samples = 3;
  double sequenceStep = 2.0;
  std::string optimiser = "fastncc";
  bool real = false;  // also a real face (needs the shared data)
  std::filesystem::path realManifest = "resources/datasets/real.json";  // from the working folder
};

// Every option of `clm3d demo`, in its help's order.
const std::vector<Option<DemoRequest>>& demoOptions();

// Runs the demo into request.out; `toolVersion` goes into the models' provenance. InputError
// before anything is written when --real's inputs are missing.
void runDemo(const DemoRequest& request, const std::string& toolVersion,
             const RunReporter& reporter);

}  // namespace clm3d
