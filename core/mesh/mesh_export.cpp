#include "core/mesh/mesh_export.hpp"

#include <array>
#include <charconv>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"

namespace clm3d {
namespace {

// Shortest text that reads back to the same float.
void appendNumber(std::string& out, float value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out.append(buffer.data(), result.ptr);
}

}  // namespace

void saveObj(const TexturedMesh& mesh, const std::filesystem::path& objPath) {
  mesh.validate();
  auto mtlPath = objPath;
  mtlPath.replace_extension(".mtl");
  auto pngPath = objPath;
  pngPath.replace_extension(".png");

  std::vector<unsigned char> png;
  if (!cv::imencode(".png", mesh.texture, png))
    throwInputError(pngPath, "cannot encode the texture");
  writeBytesAtomically(pngPath, png);

  writeTextAtomically(mtlPath,
                      "# clm3d textured mesh material\nnewmtl material0\n"
                      "Ka 1 1 1\nKd 1 1 1\nKs 0 0 0\nd 1\nillum 1\nmap_Kd " +
                          pngPath.filename().string() + "\n");

  const bool withNormals = mesh.normals.size() == mesh.positions.size();
  std::string text;
  text.reserve(mesh.vertexCount() * 96 + mesh.triangleCount() * 48);
  text += "# clm3d textured mesh: " + std::to_string(mesh.vertexCount()) + " vertices, " +
          std::to_string(mesh.triangleCount()) + " triangles\nmtllib " +
          mtlPath.filename().string() + "\n";
  for (const auto& p : mesh.positions) {
    text += "v";
    for (int i = 0; i < 3; ++i) {
      text += ' ';
      appendNumber(text, p[i]);
    }
    text += '\n';
  }
  for (const auto& t : mesh.uvs) {
    text += "vt ";
    appendNumber(text, t.x());
    text += ' ';
    appendNumber(text, t.y());
    text += '\n';
  }
  if (withNormals) {
    for (const auto& n : mesh.normals) {
      text += "vn";
      for (int i = 0; i < 3; ++i) {
        text += ' ';
        appendNumber(text, n[i]);
      }
      text += '\n';
    }
  }
  text += "usemtl material0\n";
  for (const auto& t : mesh.triangles) {
    text += "f";
    for (int i = 0; i < 3; ++i) {
      const std::string index = std::to_string(t[i] + 1);  // OBJ indices are 1-based
      text += ' ' + index + '/' + index;
      if (withNormals) text += '/' + index;
    }
    text += '\n';
  }
  writeTextAtomically(objPath, text);
}

}  // namespace clm3d
