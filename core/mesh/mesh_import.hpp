// Loading a textured mesh from OBJ (+MTL + image), PLY (texture named by a "comment TextureFile"
// header line) or glTF/GLB (embedded or external textures) through assimp, merged into the one
// TexturedMesh the renderer draws: node transforms applied, several textures packed into one atlas.
#pragma once

#include <filesystem>

#include "core/mesh/textured_mesh.hpp"

namespace clm3d {

struct MeshLoadOptions {
  // When false, a mesh without any texture loads with a 1x1 mid-grey texture (and zero UVs if it
  // has none), e.g. a morphable model that has UVs but no albedo.
  bool requireTexture = true;
};

// Throws InputError naming the file and the problem: missing file, parse failure (with
// assimp's message), no faces, a texture file that cannot be found or decoded, no texture
// coordinates, non-finite coordinates.
TexturedMesh loadTexturedMesh(const std::filesystem::path& path,
                              const MeshLoadOptions& options = {});

}  // namespace clm3d
