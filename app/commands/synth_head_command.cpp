// clm3d synth-head: writes procedural heads with exact landmarks (core/synth) as OBJ + MTL + PNG
// and LJSON, and optionally a contact sheet of each head from the thesis's 15 training views, so
// a person can check at a glance that they look like faces. The heads, files and tiles are core's
// (core/demo/procedural_heads); this file parses the options and prints.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "core/common/error.hpp"
#include "core/demo/procedural_heads.hpp"
#include "core/synth/synth_head.hpp"
#include "core/viz/contact_sheet.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct SynthHeadArgs {
  std::uint64_t seed = 1;
  std::string expression = "neutral";
  int count = 1;
  fs::path out;
  int textureSize = SynthOptions{}.textureSize;
  double faceStep = SynthOptions{}.faceStepDegrees;
  fs::path contactSheet;
  int tileSize = 160;
};

// "smile,neutral" -> {"smile", "neutral"}.
std::vector<std::string> splitNames(const std::string& text) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    names.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return names;
}

void runSynthHead(const SynthHeadArgs& args) {
  SynthOptions options;
  options.textureSize = args.textureSize;
  options.faceStepDegrees = args.faceStep;
  std::vector<cv::Mat> tiles;
  std::vector<std::string> captions;
  writeProceduralHeads(args.seed, args.count, splitNames(args.expression), options, args.out,
                       [&](const WrittenHead& written, SynthHead&& head) {
                         std::cout << written.mesh.string() << ": " << head.mesh.triangleCount()
                                   << " triangles, " << written.expression << '\n';
                         if (args.contactSheet.empty()) return;
                         HeadTiles made = trainingViewTiles(head, written.seed, args.tileSize);
                         tiles.insert(tiles.end(), made.tiles.begin(), made.tiles.end());
                         captions.insert(captions.end(), made.captions.begin(),
                                         made.captions.end());
                       });
  if (!args.contactSheet.empty()) {
    writeImage(args.contactSheet, makeContactSheet(tiles, 5, captions));
    std::cout << args.contactSheet.string() << ": " << tiles.size() << " views\n";
  }
}

}  // namespace

void addSynthHeadCommand(CLI::App& root) {
  auto args = std::make_shared<SynthHeadArgs>();
  CLI::App* cmd = root.add_subcommand(
      "synth-head", "Generate procedural textured heads with exact 3D landmarks (thesis25)");
  cmd->add_option("--seed", args->seed, "Seed of the (first) head's identity")
      ->capture_default_str();
  std::string names;
  for (const auto& name : expressionPresetNames()) names += (names.empty() ? "" : ", ") + name;
  cmd->add_option("--expression", args->expression,
                  "Expression: " + names + "; a comma-separated list is used in turn")
      ->capture_default_str();
  cmd->add_option("--count", args->count, "Number of heads, seeds seed .. seed+count-1")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Output folder (head-<seed>.obj/.mtl/.png/.ljson)")
      ->required();
  cmd->add_option("--texture-size", args->textureSize, "Texture width and height in texels")
      ->check(CLI::Range(256, 8192))
      ->capture_default_str();
  cmd->add_option("--face-step", args->faceStep, "Mesh step on the face in degrees")
      ->check(CLI::Range(0.3, 3.0))
      ->capture_default_str();
  cmd->add_option("--contact-sheet", args->contactSheet,
                  "Also write a PNG of every head from the 15 training views");
  cmd->add_option("--tile-size", args->tileSize, "Contact sheet tile size in pixels")
      ->check(CLI::Range(64, 1024))
      ->capture_default_str();
  cmd->callback([args] { runSynthHead(*args); });
}

}  // namespace clm3d::cli
