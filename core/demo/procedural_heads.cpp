#include "core/demo/detail/procedural_heads.hpp"

#include <cmath>

#include "core/common/error.hpp"
#include "core/mesh/mesh_export.hpp"
#include "core/render/view_tiles.hpp"
#include "core/scheme/landmark_file.hpp"

namespace clm3d {

namespace fs = std::filesystem;

namespace {

const Eigen::Vector3d kHeadPivot(0.0, -45.0, -60.0);  // about the middle of the head and neck

}  // namespace

void writeProceduralHeads(std::uint64_t firstSeed, int count,
                          const std::vector<std::string>& expressions, const SynthOptions& options,
                          const fs::path& folder, const HeadWritten& onHead) {
  if (expressions.empty()) throw InputError("procedural heads: no expression given");
  std::vector<Expression> presets;
  for (const std::string& name : expressions) presets.push_back(Expression::preset(name));
  options.validate();
  fs::create_directories(folder);
  for (int i = 0; i < count; ++i) {
    const std::uint64_t seed = firstSeed + static_cast<std::uint64_t>(i);
    const std::size_t which = static_cast<std::size_t>(i) % presets.size();
    SynthHead head = generateHead(seed, presets[which], options);
    const std::string stem = "head-" + std::to_string(seed);
    WrittenHead written{seed, expressions[which], folder / (stem + ".obj"),
                        folder / (stem + ".ljson")};
    saveObj(head.mesh, written.mesh);
    writeLandmarks(written.landmarks, head.landmarks, Scheme::thesis25());
    if (onHead) onHead(written, std::move(head));
  }
}

HeadTiles trainingViewTiles(const SynthHead& head, std::uint64_t seed, int tileSize) {
  const std::vector<ViewAngles> views = trainingViewAngles();
  HeadTiles made;
  made.tiles = renderTilesAboutPivot(head.mesh, views, tileSize, kHeadPivot);
  for (const ViewAngles& view : views) {
    made.captions.push_back("#" + std::to_string(seed) + " y" +
                            std::to_string(std::lround(view.yawDeg)) + " p" +
                            std::to_string(std::lround(view.pitchDeg)));
  }
  return made;
}

}  // namespace clm3d
