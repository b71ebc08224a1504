// What `clm3d synth-head` is asked for, described once as an option table (the CLI builds the
// command's options from it), and its run: procedural heads written as OBJ + MTL + PNG and LJSON
// (core/demo/procedural_heads) and optionally a contact sheet of each from the 15 training views.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/common/option_table.hpp"
#include "core/synth/synth_head.hpp"

namespace clm3d {

struct SynthHeadRequest {
  std::uint64_t seed = 1;
  std::string expression = "neutral";  // a preset, or several separated by commas, used in turn
  int count = 1;
  std::filesystem::path out;
  int textureSize = SynthOptions{}.textureSize;
  double faceStep = SynthOptions{}.faceStepDegrees;
  std::filesystem::path contactSheet;
  int tileSize = 160;
};

// Every option of `clm3d synth-head`, in its help's order.
const std::vector<Option<SynthHeadRequest>>& synthHeadOptions();

// Writes the heads (and the sheet); `print` hears a line for each file as it is written.
void runSynthHeads(const SynthHeadRequest& request,
                   const std::function<void(const std::string&)>& print);

}  // namespace clm3d
