// clm3d synth-head: procedural textured heads with exact landmarks, and optionally a contact sheet
// of each from the 15 training views. The options and the run are core's
// (core/demo/synth_head_request); this file adds them and prints each file as it is written.
#include <iostream>

#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/demo/synth_head_request.hpp"

namespace clm3d::cli {

void addSynthHeadCommand(CLI::App& root) {
  addRequestCommand(root, "synth-head",
                    "Generate procedural textured heads with exact 3D landmarks (thesis25)",
                    synthHeadOptions(), [](const SynthHeadRequest& request, const CLI::App&) {
                      runSynthHeads(request, [](const std::string& line) { std::cout << line; });
                      return std::string();
                    });
}

}  // namespace clm3d::cli
