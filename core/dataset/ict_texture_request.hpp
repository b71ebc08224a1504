// What `clm3d ict-texture` is asked for, described once as an option table (the CLI builds the
// command's options from it), and its run: the ICT-FaceKit neutral registered onto a textured
// scan, the scan's texture baked into ICT's UV layout, the registered neutral written as OBJ + MTL
// + PNG, optionally random textured identities and their contact sheet (docs/texture-transfer.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/common/option_table.hpp"

namespace clm3d {

struct IctTextureRequest {
  std::filesystem::path model, vertices, scan, landmarks, out;
  std::string up = "+y", front = "+z";
  double scale = 1.0;
  int textureSize = 1024;
  int samples = 0;
  std::uint64_t seedOffset = 0;
  std::filesystem::path contactSheet;
  int tileSize = 256;
};

// Every option of `clm3d ict-texture`, in its help's order.
const std::vector<Option<IctTextureRequest>>& ictTextureOptions();

// Writes the registered neutral (and the samples) into request.out and returns the report the
// command prints: the files, the surface and landmark residuals, the texels baked, the times.
std::string runIctTexture(const IctTextureRequest& request);

}  // namespace clm3d
