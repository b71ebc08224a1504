// Textured head meshes of random MakeHuman identities (../shared/data/makehuman, MakeHuman 1.1
// assets, CC0): the base mesh's `body` group cropped to the head, identity shape targets with
// random weights drawn from a seed, optional expression targets, one of the skin textures and an
// eye mesh with an eye texture fitted into each socket, skin and eye packed into one texture atlas.
// The thesis25 landmarks come from a table of base-mesh vertex indices
// (tests/fixtures/makehuman/thesis25_vertices.json), so every identity has exact ground truth.
// Output: millimetres, +x = the subject's left, +y up, +z out of the face (the base mesh's axes;
// its unit is the decimetre). Generation is deterministic for a seed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/mesh/textured_mesh.hpp"
#include "core/scheme/landmark_set.hpp"

namespace clm3d {

struct MakeHumanOptions {
  std::vector<std::string> skins;  // skin file stems in skins/ to draw from; empty = all
  std::vector<std::string> eyes;   // eye texture stems in eyes/ ("brown_eye"); empty = all
  // Expressions to load: "neutral" or expression-unit target stems joined by '+'
  // ("mouth-open", "eyebrows-left-up+eyebrows-right-up").
  std::vector<std::string> expressions{"neutral"};
  std::string expressionUnits = "caucasian";  // folder under targets/expression/units/
  double identityWeight = 0.5;  // a two-sided modifier's weight is uniform in [-w, w]; one-sided
                                // targets (head-oval, ...) in [0, w]
  double asymmetry = 0.1;       // a right-side modifier's weight = the left one's + uniform(-a, a)
  double expressionWeight = 0.8;  // weight of each expression target
  int textureSize = 1024;         // the skin's part of the atlas is textureSize x textureSize
};

// Everything one identity is built from, loaded once and shared (read-only, thread-safe) by all
// identities of a manifest source: base mesh and head crop, identity and expression targets, eye
// mesh, landmark vertex table; skins and eye textures are read on first use and cached.
class MakeHumanAssets {
 public:
  // `root` holds base/base.obj, skins/*.png, eyes/{high-poly.obj,*_eye.png},
  // targets/<region>/*.target. `landmarkVertices` is one base-mesh vertex index per landmark
  // (-1 = missing). Throws InputError naming the file (and line) that is missing or malformed, or
  // an option that names no file (a skin, eye texture or expression target); Cancelled on cancel.
  static std::shared_ptr<const MakeHumanAssets> load(const std::filesystem::path& root,
                                                     const std::vector<int>& landmarkVertices,
                                                     const MakeHumanOptions& options,
                                                     const ProgressCallback& progress = {},
                                                     const CancelToken* cancel = nullptr);
  ~MakeHumanAssets();
  MakeHumanAssets(const MakeHumanAssets&) = delete;
  MakeHumanAssets& operator=(const MakeHumanAssets&) = delete;

  const MakeHumanOptions& options() const;
  // Identity modifiers: an opposed pair (decr/incr, down/up, ...) is one signed weight, and a
  // left/right pair of such modifiers counts once.
  std::size_t identityModifierCount() const;
  std::size_t baseVertexCount() const;

  struct Head {
    TexturedMesh mesh;       // mm, +x subject's left, +y up, +z front (not centred)
    LandmarkSet landmarks;   // 3D, one per table entry, same coordinates
    std::string skin, eyes;  // texture stems drawn for this identity
  };
  // Identity `seed` (its skin, eye texture and target weights all follow from the seed) with
  // `expression`, which must be one of options().expressions (InputError otherwise). Same seed,
  // same head. `symmetric` forces asymmetry 0 (left and right modifiers share their weight).
  Head generate(std::uint64_t seed, const std::string& expression, bool symmetric = false) const;

 private:
  struct Impl;
  MakeHumanAssets();
  std::unique_ptr<Impl> impl_;
};

}  // namespace clm3d
