#include "core/demo/synth_head_request.hpp"

#include <algorithm>

#include "core/demo/detail/procedural_heads.hpp"
#include "core/viz/contact_sheet.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {
namespace synth_head_request_detail {

using R = SynthHeadRequest;

std::string expressionNames() {
  std::string names;
  for (const auto& name : expressionPresetNames()) names += (names.empty() ? "" : ", ") + name;
  return names;
}

std::vector<Option<R>> makeOptions() {
  return {
      integerOption<R>(commandOption("seed", "Seed of the (first) head's identity", 0, 9e18),
                       &R::seed),
      textOption<R>(commandOption("expression", "Expression: " + expressionNames() +
                                                    "; a comma-separated list is used in turn"),
                    &R::expression),
      integerOption<R>(
          commandOption("count", "Number of heads, seeds seed .. seed+count-1", 1, 10000),
          &R::count),
      textOption<R>(requiredOption("out", "Output folder (head-<seed>.obj/.mtl/.png/.ljson)"),
                    &R::out),
      integerOption<R>(
          commandOption("texture-size", "Texture width and height in texels", 256, 8192),
          &R::textureSize),
      realOption<R>(commandOption("face-step", "Mesh step on the face in degrees", 0.3, 3.0),
                    &R::faceStep),
      textOption<R>(commandOption("contact-sheet",
                                  "Also write a PNG of every head from the 15 training views"),
                    &R::contactSheet),
      integerOption<R>(commandOption("tile-size", "Contact sheet tile size in pixels", 64, 1024),
                       &R::tileSize),
  };
}

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

}  // namespace synth_head_request_detail

const std::vector<Option<SynthHeadRequest>>& synthHeadOptions() {
  static const std::vector<Option<SynthHeadRequest>> table =
      synth_head_request_detail::makeOptions();
  return table;
}

void runSynthHeads(const SynthHeadRequest& args,
                   const std::function<void(const std::string&)>& print) {
  SynthOptions options;
  options.textureSize = args.textureSize;
  options.faceStepDegrees = args.faceStep;
  std::vector<cv::Mat> tiles;
  std::vector<std::string> captions;
  writeProceduralHeads(
      args.seed, args.count, synth_head_request_detail::splitNames(args.expression), options,
      args.out, [&](const WrittenHead& written, SynthHead&& head) {
        print(written.mesh.string() + ": " + std::to_string(head.mesh.triangleCount()) +
              " triangles, " + written.expression + '\n');
        if (args.contactSheet.empty()) return;
        HeadTiles made = trainingViewTiles(head, written.seed, args.tileSize);
        tiles.insert(tiles.end(), made.tiles.begin(), made.tiles.end());
        captions.insert(captions.end(), made.captions.begin(), made.captions.end());
      });
  if (!args.contactSheet.empty()) {
    writeImage(args.contactSheet, makeContactSheet(tiles, 5, captions));
    print(args.contactSheet.string() + ": " + std::to_string(tiles.size()) + " views\n");
  }
}

}  // namespace clm3d
