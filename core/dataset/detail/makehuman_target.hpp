// MakeHuman shape targets (.target files): sparse per-vertex offsets "index dx dy dz" on the
// MakeHuman base mesh, one vertex a line, '#' comments. A weighted sum of targets added to the base
// mesh is how MakeHuman builds an identity or an expression; this is the reader and that sum.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace clm3d {

struct MorphTarget {
  std::string name;                      // file stem, e.g. "nose-hump-incr"
  std::vector<int> indices;              // 0-based base-mesh vertex indices, strictly in file order
  std::vector<Eigen::Vector3f> offsets;  // one per index, in the base mesh's units
};

// Parses the text of a .target file. Every non-empty line that is not a comment must hold an
// integer vertex index below vertexCount and three finite numbers; otherwise throws InputError
// "FILE:LINE: ..." naming `file`. A vertex listed twice is an error too.
MorphTarget parseMorphTarget(std::string_view text, const std::filesystem::path& file,
                             std::size_t vertexCount);

// Reads and parses a .target file (InputError naming it if it cannot be read).
MorphTarget readMorphTarget(const std::filesystem::path& file, std::size_t vertexCount);

// positions[i] += weight * offset for every vertex of the target. positions must hold at least as
// many vertices as the target was parsed for (std::out_of_range otherwise).
void applyMorphTarget(const MorphTarget& target, float weight,
                      std::vector<Eigen::Vector3f>& positions);

}  // namespace clm3d
