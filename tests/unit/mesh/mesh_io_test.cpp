// Mesh import and export: the james scan, round trips through OBJ, PLY and glTF written here, a
// texture atlas, untextured meshes, and broken inputs (each an InputError naming the file).
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/mesh/mesh_export.hpp"
#include "core/mesh/mesh_import.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::TempDir;
using test::writeFile;

// The colour of the texture at a UV (0,0 = bottom-left), nearest texel.
cv::Vec3b sample(const cv::Mat& texture, const Eigen::Vector2f& uv) {
  const int x = std::clamp(static_cast<int>(uv.x() * texture.cols), 0, texture.cols - 1);
  const int y = std::clamp(static_cast<int>((1.0F - uv.y()) * texture.rows), 0, texture.rows - 1);
  return texture.at<cv::Vec3b>(y, x);
}

// 16x16: top half red, bottom half green (BGR), so a vertical flip shows.
cv::Mat twoToneTexture() {
  cv::Mat texture(16, 16, CV_8UC3, cv::Scalar(0, 0, 255));
  texture(cv::Rect(0, 8, 16, 8)).setTo(cv::Scalar(0, 255, 0));
  return texture;
}

// A unit-ish square with the two-tone texture: UV v = 1 at the top (+y).
TexturedMesh square() {
  TexturedMesh mesh;
  mesh.positions = {{-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0}};
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.texture = twoToneTexture();
  mesh.source = "square";
  return mesh;
}

// The UV of the vertex at a position (meshes may reorder vertices).
Eigen::Vector2f uvAt(const TexturedMesh& mesh, const Eigen::Vector3f& position) {
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    if ((mesh.positions[i] - position).norm() < 1e-4F) return mesh.uvs[i];
  }
  ADD_FAILURE() << "no vertex at " << position.transpose();
  return {-1, -1};
}

void expectInputErrorNaming(const std::filesystem::path& path, const std::string& fragment = "",
                            const MeshLoadOptions& options = {}) {
  try {
    loadTexturedMesh(path, options);
    ADD_FAILURE() << "expected InputError for " << path;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
    if (!fragment.empty()) {
      EXPECT_NE(message.find(fragment), std::string::npos) << message;
    }
  }
}

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* const kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (bytes[i] << 16U) | (bytes[i + 1] << 8U) | bytes[i + 2];
    for (int k = 3; k >= 0; --k) out += kAlphabet[(v >> (6U * static_cast<unsigned>(k))) & 63U];
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = bytes[i] << 16U;
    out += std::string{kAlphabet[(v >> 18U) & 63U], kAlphabet[(v >> 12U) & 63U], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (bytes[i] << 16U) | (bytes[i + 1] << 8U);
    out += std::string{kAlphabet[(v >> 18U) & 63U], kAlphabet[(v >> 12U) & 63U],
                       kAlphabet[(v >> 6U) & 63U], '='};
  }
  return out;
}

template <typename T>
void appendBytes(std::vector<unsigned char>& out, const std::vector<T>& values) {
  const auto* p = reinterpret_cast<const unsigned char*>(values.data());
  out.insert(out.end(), p, p + values.size() * sizeof(T));
}

TEST(MeshImport, JamesLoadsWithTexture) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const TexturedMesh mesh = loadTexturedMesh(data / "scans/james/james.obj");
  EXPECT_EQ(mesh.triangleCount(), 12228U);
  // 6393 positions in the file, split where a position has several UVs (6680 in the file).
  EXPECT_GE(mesh.vertexCount(), 6393U);
  EXPECT_LE(mesh.vertexCount(), 6680U + 200U);
  EXPECT_EQ(mesh.texture.size(), cv::Size(2400, 1600));
  EXPECT_EQ(mesh.texture.type(), CV_8UC3);
  EXPECT_EQ(mesh.normals.size(), mesh.vertexCount());
  const Eigen::AlignedBox3f box = mesh.bounds();
  EXPECT_NEAR(box.min().y(), -171.3423F, 1e-3F);
  EXPECT_NEAR(box.max().y(), 149.899429F, 1e-3F);
  EXPECT_NE(mesh.source.find("james.obj"), std::string::npos);
  EXPECT_NO_THROW(mesh.validate());
}

TEST(MeshImport, IctFaceKitLoadsWithoutTextureWhenAllowed) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const auto path = data / "morphable/ict-facekit/generic_neutral_mesh.obj";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found";
  expectInputErrorNaming(path, "texture");
  MeshLoadOptions options;
  options.requireTexture = false;
  const TexturedMesh mesh = loadTexturedMesh(path, options);
  EXPECT_GE(mesh.vertexCount(), 26719U);
  EXPECT_GT(mesh.triangleCount(), 0U);
  EXPECT_EQ(mesh.texture.size(), cv::Size(1, 1));
  EXPECT_EQ(mesh.texture.at<cv::Vec3b>(0, 0), cv::Vec3b(128, 128, 128));
  EXPECT_NO_THROW(mesh.validate());
}

TEST(MeshExport, ObjRoundTrip) {
  TempDir dir;
  TexturedMesh original = square();
  original.computeNormals();
  saveObj(original, dir / "square.obj");
  EXPECT_TRUE(std::filesystem::exists(dir / "square.mtl"));
  EXPECT_TRUE(std::filesystem::exists(dir / "square.png"));
  const TexturedMesh loaded = loadTexturedMesh(dir / "square.obj");
  EXPECT_EQ(loaded.vertexCount(), 4U);
  EXPECT_EQ(loaded.triangleCount(), 2U);
  EXPECT_EQ(cv::norm(loaded.texture, original.texture, cv::NORM_INF), 0.0);
  for (std::size_t i = 0; i < original.vertexCount(); ++i) {
    EXPECT_TRUE(uvAt(loaded, original.positions[i]).isApprox(original.uvs[i]));
  }
  // The top of the square samples the top (red) half of the texture.
  EXPECT_EQ(
      sample(loaded.texture, uvAt(loaded, {-10, 10, 0}) * 0.9F + Eigen::Vector2f(0.05F, 0.05F)),
      cv::Vec3b(0, 0, 255));
  for (const auto& n : loaded.normals) EXPECT_NEAR(n.z(), 1.0F, 1e-5F);
}

TEST(MeshImport, PlyWithTextureCommentRoundTrip) {
  TempDir dir;
  const TexturedMesh original = square();
  ASSERT_TRUE(cv::imwrite((dir / "skin.png").string(), original.texture));
  std::string ply =
      "ply\nformat ascii 1.0\ncomment TextureFile skin.png\nelement vertex 4\n"
      "property float x\nproperty float y\nproperty float z\nproperty float s\nproperty float t\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& p = original.positions[i];
    const auto& t = original.uvs[i];
    ply += std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + " " +
           std::to_string(t.x()) + " " + std::to_string(t.y()) + "\n";
  }
  ply += "3 0 1 2\n3 0 2 3\n";
  writeFile(dir / "square.ply", ply);
  const TexturedMesh loaded = loadTexturedMesh(dir / "square.ply");
  EXPECT_EQ(loaded.triangleCount(), 2U);
  EXPECT_EQ(loaded.vertexCount(), 4U);
  EXPECT_EQ(cv::norm(loaded.texture, original.texture, cv::NORM_INF), 0.0);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(uvAt(loaded, original.positions[i]).isApprox(original.uvs[i]))
        << uvAt(loaded, original.positions[i]).transpose();
  }
  // Without the texture file: an error naming the PLY and the texture.
  std::filesystem::remove(dir / "skin.png");
  expectInputErrorNaming(dir / "square.ply", "skin.png");
}

enum class GltfKind { DataUris, ExternalTexture, Glb };

// A glTF 2.0 square with a node transform (translation by +100 in x) that the importer must
// apply: buffer and PNG texture as data URIs, or the texture as a file beside it ("skin.png",
// written by the caller), or everything in one binary .glb.
std::string gltfSquare(const TexturedMesh& mesh, GltfKind kind) {
  std::vector<float> positions;
  std::vector<float> uvs;
  for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
    const auto& p = mesh.positions[i];
    positions.insert(positions.end(), {p.x(), p.y(), p.z()});
    uvs.insert(uvs.end(), {mesh.uvs[i].x(), 1.0F - mesh.uvs[i].y()});  // glTF: (0,0) = top-left
  }
  std::vector<std::uint16_t> indices;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) indices.push_back(static_cast<std::uint16_t>(t[k]));
  }
  std::vector<unsigned char> buffer;
  appendBytes(buffer, positions);
  appendBytes(buffer, uvs);
  appendBytes(buffer, indices);
  buffer.resize((buffer.size() + 3) / 4 * 4, 0);
  std::vector<unsigned char> png;
  cv::imencode(".png", mesh.texture, png);
  const std::size_t uvOffset = positions.size() * 4;
  const std::size_t indexOffset = uvOffset + uvs.size() * 4;
  const std::size_t pngOffset = buffer.size();
  std::string image;
  if (kind == GltfKind::DataUris) image = R"({"uri":"data:image/png;base64,)" + base64(png) + "\"}";
  if (kind == GltfKind::ExternalTexture) image = R"({"uri":"skin.png"})";
  if (kind == GltfKind::Glb) {
    image = R"({"bufferView":3,"mimeType":"image/png"})";
    buffer.insert(buffer.end(), png.begin(), png.end());
    buffer.resize((buffer.size() + 3) / 4 * 4, 0);
  }
  const std::string bufferUri =
      kind == GltfKind::Glb
          ? ""
          : R"(,"uri":"data:application/octet-stream;base64,)" + base64(buffer) + "\"";
  std::string json =
      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
  "nodes":[{"mesh":0,"translation":[100,0,0]}],
  "meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"indices":2,"material":0}]}],
  "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],
  "textures":[{"source":0}],
  "images":[)" +
      image + R"(],
  "buffers":[{"byteLength":)" +
      std::to_string(buffer.size()) + bufferUri + R"(}],
  "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" +
      std::to_string(uvOffset) + R"(},
    {"buffer":0,"byteOffset":)" +
      std::to_string(uvOffset) + R"(,"byteLength":)" + std::to_string(indexOffset - uvOffset) +
      R"(},
    {"buffer":0,"byteOffset":)" +
      std::to_string(indexOffset) + R"(,"byteLength":)" + std::to_string(indices.size() * 2) + R"(},
    {"buffer":0,"byteOffset":)" +
      std::to_string(pngOffset) + R"(,"byteLength":)" + std::to_string(png.size()) + R"(}],
  "accessors":[
    {"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[-10,-10,0],"max":[10,10,0]},
    {"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"},
    {"bufferView":2,"componentType":5123,"count":6,"type":"SCALAR"}]})";
  if (kind != GltfKind::Glb) return json;
  json.resize((json.size() + 3) / 4 * 4, ' ');
  // GLB: 12-byte header, then a JSON chunk and a BIN chunk (little-endian lengths and tags).
  std::vector<std::uint32_t> header = {
      0x46546C67U, 2U, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + buffer.size())};
  std::vector<unsigned char> glb;
  appendBytes(glb, header);
  appendBytes(glb,
              std::vector<std::uint32_t>{static_cast<std::uint32_t>(json.size()), 0x4E4F534AU});
  glb.insert(glb.end(), json.begin(), json.end());
  appendBytes(glb,
              std::vector<std::uint32_t>{static_cast<std::uint32_t>(buffer.size()), 0x004E4942U});
  glb.insert(glb.end(), buffer.begin(), buffer.end());
  return std::string(glb.begin(), glb.end());
}

TEST(MeshImport, GltfAndGlbWithTexturesAndNodeTransform) {
  const TexturedMesh original = square();
  for (const auto& [kind, name] : {std::pair{GltfKind::DataUris, "embedded.gltf"},
                                   std::pair{GltfKind::ExternalTexture, "external.gltf"},
                                   std::pair{GltfKind::Glb, "binary.glb"}}) {
    SCOPED_TRACE(name);
    TempDir dir;
    if (kind == GltfKind::ExternalTexture) {
      ASSERT_TRUE(cv::imwrite((dir / "skin.png").string(), original.texture));
    }
    writeFile(dir / name, gltfSquare(original, kind));
    const TexturedMesh loaded = loadTexturedMesh(dir / name);
    EXPECT_EQ(loaded.triangleCount(), 2U);
    EXPECT_EQ(cv::norm(loaded.texture, original.texture, cv::NORM_INF), 0.0);
    EXPECT_NEAR(loaded.bounds().center().x(), 100.0F, 1e-4F);
    for (std::size_t i = 0; i < 4; ++i) {
      const Eigen::Vector3f moved = original.positions[i] + Eigen::Vector3f(100, 0, 0);
      const Eigen::Vector2f uv = uvAt(loaded, moved);
      EXPECT_TRUE(uv.isApprox(original.uvs[i], 1e-5F)) << uv.transpose();
    }
    if (kind == GltfKind::ExternalTexture) {
      std::filesystem::remove(dir / "skin.png");
      expectInputErrorNaming(dir / name, "skin.png");
    }
  }
}

TEST(MeshImport, SeveralTexturesArePackedIntoOneAtlas) {
  TempDir dir;
  cv::Mat red(32, 16, CV_8UC3, cv::Scalar(0, 0, 255));
  red(cv::Rect(0, 0, 16, 4)).setTo(cv::Scalar(255, 255, 255));  // white strip at the top
  const cv::Mat blue(8, 24, CV_8UC3, cv::Scalar(255, 0, 0));
  ASSERT_TRUE(cv::imwrite((dir / "red.png").string(), red));
  ASSERT_TRUE(cv::imwrite((dir / "blue.png").string(), blue));
  writeFile(dir / "two.mtl",
            "newmtl a\nKd 1 1 1\nmap_Kd red.png\nnewmtl b\nKd 1 1 1\nmap_Kd blue.png\n"
            "newmtl c\nKd 1 1 0\n");
  writeFile(
      dir / "two.obj",
      "mtllib two.mtl\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nv 3 1 0\nv 5 0 0\nv 6 0 0\nv 6 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.95\n"
      "usemtl a\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n"
      "usemtl b\nf 5/1 6/2 7/3\n"
      "usemtl c\nf 8/5 9/5 10/5\n");
  const TexturedMesh mesh = loadTexturedMesh(dir / "two.obj");
  EXPECT_EQ(mesh.triangleCount(), 4U);
  EXPECT_GE(mesh.texture.cols * mesh.texture.rows, 32 * 16 + 8 * 24);
  // Each part's UV centre samples its own texture; near v = 1 the red texture is white.
  const auto centreOf = [&](const std::vector<Eigen::Vector3f>& corners, float v) {
    Eigen::Vector2f lo = uvAt(mesh, corners[0]);
    Eigen::Vector2f hi = uvAt(mesh, corners[1]);
    return Eigen::Vector2f(0.5F * (lo.x() + hi.x()), lo.y() + v * (hi.y() - lo.y()));
  };
  EXPECT_EQ(sample(mesh.texture, centreOf({{0, 0, 0}, {1, 1, 0}}, 0.5F)), cv::Vec3b(0, 0, 255));
  EXPECT_EQ(sample(mesh.texture, centreOf({{0, 0, 0}, {1, 1, 0}}, 0.97F)),
            cv::Vec3b(255, 255, 255));
  EXPECT_EQ(sample(mesh.texture, centreOf({{2, 0, 0}, {3, 1, 0}}, 0.5F)), cv::Vec3b(255, 0, 0));
  // The untextured material becomes a swatch of its diffuse colour (yellow).
  EXPECT_EQ(sample(mesh.texture, uvAt(mesh, {5, 0, 0})), cv::Vec3b(0, 255, 255));
}

TEST(MeshImport, UntexturedWithoutUvsGetsGreyAndZeroUvs) {
  TempDir dir;
  writeFile(dir / "plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  expectInputErrorNaming(dir / "plain.obj");
  MeshLoadOptions options;
  options.requireTexture = false;
  const TexturedMesh mesh = loadTexturedMesh(dir / "plain.obj", options);
  EXPECT_EQ(mesh.texture.size(), cv::Size(1, 1));
  for (const auto& uv : mesh.uvs) EXPECT_EQ(uv, Eigen::Vector2f::Zero());
}

class BrokenMesh : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(cv::imwrite((dir / "skin.png").string(), twoToneTexture()));
    writeFile(dir / "skin.mtl", "newmtl skin\nKd 1 1 1\nmap_Kd skin.png\n");
  }
  TempDir dir;
  const std::string header = "mtllib skin.mtl\nusemtl skin\n";
  const std::string vertices =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
};

TEST_F(BrokenMesh, NonexistentFile) {
  expectInputErrorNaming(dir / "nothere.obj", "not found");
}

TEST_F(BrokenMesh, TruncatedObj) {
  // Cut in the middle of the vertex list: faces refer to vertices that are not there.
  writeFile(dir / "cut.obj", header + "v 0 0 0\nv 1 0 0\nvt 0 0\nf 1/1 2/1 3/1\nf 1/1 3/1 4");
  expectInputErrorNaming(dir / "cut.obj");
}

TEST_F(BrokenMesh, MissingTextureFile) {
  writeFile(dir / "other.mtl", "newmtl skin\nmap_Kd gone.jpg\n");
  writeFile(dir / "gone.obj", "mtllib other.mtl\nusemtl skin\n" + vertices + "f 1/1 2/2 3/3\n");
  expectInputErrorNaming(dir / "gone.obj", "gone.jpg");
}

TEST_F(BrokenMesh, UndecodableTexture) {
  writeFile(dir / "bad.png", "not an image");
  writeFile(dir / "bad.mtl", "newmtl skin\nmap_Kd bad.png\n");
  writeFile(dir / "badtex.obj", "mtllib bad.mtl\nusemtl skin\n" + vertices + "f 1/1 2/2 3/3\n");
  expectInputErrorNaming(dir / "badtex.obj", "bad.png");
}

TEST_F(BrokenMesh, ObjWithoutUvs) {
  writeFile(dir / "nouv.obj", header + "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n");
  expectInputErrorNaming(dir / "nouv.obj", "texture coordinates");
}

TEST_F(BrokenMesh, ObjWithoutFaces) {
  writeFile(dir / "nofaces.obj", header + vertices);
  expectInputErrorNaming(dir / "nofaces.obj", "faces");
}

TEST_F(BrokenMesh, NanCoordinate) {
  writeFile(dir / "nan.obj", header +
                                 "v 0 0 0\nv nan 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
                                 "f 1/1 2/2 3/3\n");
  expectInputErrorNaming(dir / "nan.obj", "finite");
}

TEST_F(BrokenMesh, GarbageFile) {
  writeFile(dir / "garbage.glb", "glTF this is not a binary glTF");
  expectInputErrorNaming(dir / "garbage.glb");
}

TEST(TexturedMesh, NormalsAreSmoothAcrossUvSeams) {
  // Two triangles folded at the x = 0 edge, the edge's vertices duplicated (a UV seam).
  TexturedMesh mesh;
  mesh.positions = {{0, 0, 0}, {0, 1, 0}, {-1, 0, -1}, {0, 0, 0}, {0, 1, 0}, {1, 0, -1}};
  mesh.triangles = {{0, 2, 1}, {3, 4, 5}};
  mesh.computeNormals();
  ASSERT_EQ(mesh.normals.size(), 6U);
  // The seam vertices get the same, averaged normal; the outer ones keep their face's.
  EXPECT_TRUE(mesh.normals[0].isApprox(mesh.normals[3]));
  EXPECT_NEAR(mesh.normals[0].x(), 0.0F, 1e-6F);
  EXPECT_NEAR(mesh.normals[0].norm(), 1.0F, 1e-6F);
  EXPECT_NEAR(std::abs(mesh.normals[2].x()), std::sqrt(0.5F), 1e-5F);
}

TEST(TexturedMesh, ValidateNamesTheSource) {
  TexturedMesh mesh = square();
  mesh.source = "face.obj";
  EXPECT_NO_THROW(mesh.validate());
  mesh.triangles.push_back({0, 1, 7});
  try {
    mesh.validate();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face.obj"), std::string::npos);
  }
  mesh = square();
  mesh.uvs.pop_back();
  EXPECT_THROW(mesh.validate(), InputError);
  mesh = square();
  mesh.texture = cv::Mat();
  EXPECT_THROW(mesh.validate(), InputError);
  mesh = square();
  mesh.translate({1, 2, 3});
  EXPECT_TRUE(mesh.bounds().min().isApprox(Eigen::Vector3f(-9, -8, 3)));
}

}  // namespace
}  // namespace clm3d
