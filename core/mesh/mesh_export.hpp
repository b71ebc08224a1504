// Saving a TexturedMesh as OBJ + MTL + PNG texture (each written atomically), the most widely
// readable textured format (Blender, MeshLab, and loadTexturedMesh itself).
#pragma once

#include <filesystem>

#include "core/mesh/textured_mesh.hpp"

namespace clm3d {

// Writes objPath, objPath with extension .mtl and objPath with extension .png (the texture).
// Throws InputError naming the file if one cannot be written, or if the mesh is invalid.
void saveObj(const TexturedMesh& mesh, const std::filesystem::path& objPath);

}  // namespace clm3d
