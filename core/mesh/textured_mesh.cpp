#include "core/mesh/textured_mesh.hpp"

#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

std::string sourceName(const std::string& source) {
  return source.empty() ? "mesh" : source;
}

}  // namespace

void TexturedMesh::computeNormals() {
  // Vertices split at UV seams share a position: accumulate per distinct position so the
  // shading stays smooth across seams.
  using Key = std::tuple<float, float, float>;
  std::map<Key, int> groupOf;
  std::vector<int> group(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const auto& p = positions[i];
    group[i] =
        groupOf.emplace(Key{p.x(), p.y(), p.z()}, static_cast<int>(groupOf.size())).first->second;
  }
  std::vector<Eigen::Vector3f> sums(groupOf.size(), Eigen::Vector3f::Zero());
  for (const auto& t : triangles) {
    const Eigen::Vector3f& a = positions[static_cast<std::size_t>(t.x())];
    const Eigen::Vector3f& b = positions[static_cast<std::size_t>(t.y())];
    const Eigen::Vector3f& c = positions[static_cast<std::size_t>(t.z())];
    const Eigen::Vector3f areaNormal = (b - a).cross(c - a);  // length = twice the area
    for (int k = 0; k < 3; ++k)
      sums[static_cast<std::size_t>(group[static_cast<std::size_t>(t[k])])] += areaNormal;
  }
  normals.resize(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Eigen::Vector3f& sum = sums[static_cast<std::size_t>(group[i])];
    const float length = sum.norm();
    normals[i] = length > 0.0F ? Eigen::Vector3f(sum / length) : Eigen::Vector3f::UnitZ();
  }
}

Eigen::AlignedBox3f TexturedMesh::bounds() const {
  Eigen::AlignedBox3f box;
  for (const auto& p : positions) box.extend(p);
  return box;
}

void TexturedMesh::translate(const Eigen::Vector3f& offset) {
  for (auto& p : positions) p += offset;
}

void TexturedMesh::validate() const {
  const std::string name = sourceName(source);
  if (positions.empty() || triangles.empty()) throwInputError(name, "the mesh has no faces");
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!positions[i].allFinite()) {
      throwInputError(name, "vertex " + std::to_string(i + 1) + " has a non-finite coordinate");
    }
  }
  const auto count = static_cast<int>(positions.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    if (t.minCoeff() < 0 || t.maxCoeff() >= count) {
      throwInputError(name,
                      "triangle " + std::to_string(i + 1) + " refers to a vertex out of range");
    }
  }
  if (uvs.size() != positions.size()) {
    throwInputError(name, uvs.empty() ? "the mesh has no texture coordinates"
                                      : "texture coordinates and vertices differ in number");
  }
  for (std::size_t i = 0; i < uvs.size(); ++i) {
    if (!uvs[i].allFinite()) {
      throwInputError(name, "texture coordinate " + std::to_string(i + 1) + " is not finite");
    }
  }
  if (!normals.empty() && normals.size() != positions.size()) {
    throwInputError(name, "normals and vertices differ in number");
  }
  if (texture.empty()) throwInputError(name, "the mesh has no texture image");
  if (texture.depth() != CV_8U ||
      (texture.channels() != 3 && texture.channels() != 4 && texture.channels() != 1)) {
    throwInputError(name, "the texture must be an 8-bit image");
  }
}

}  // namespace clm3d
