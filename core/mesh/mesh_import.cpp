#include "core/mesh/mesh_import.hpp"

#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

// One texture image (or a flat-colour swatch for an untextured material) of the scene.
struct Image {
  cv::Mat bgr;
  bool swatch = false;  // UVs of meshes using it all point at its centre
};

struct Part {
  std::size_t firstVertex = 0;
  std::size_t vertexCount = 0;
  int image = -1;  // index into images, -1 = none
  bool hasUvs = false;
};

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

cv::Mat decodeEmbedded(const aiTexture& texture) {
  if (texture.mHeight == 0) {  // compressed (PNG, JPEG...) of mWidth bytes
    const cv::Mat bytes(1, static_cast<int>(texture.mWidth), CV_8U,
                        const_cast<aiTexel*>(texture.pcData));
    return cv::imdecode(bytes, cv::IMREAD_COLOR);
  }
  // aiTexel is {b, g, r, a}: BGRA rows, top row first.
  const cv::Mat bgra(static_cast<int>(texture.mHeight), static_cast<int>(texture.mWidth), CV_8UC4,
                     const_cast<aiTexel*>(texture.pcData));
  cv::Mat bgr;
  cv::cvtColor(bgra, bgr, cv::COLOR_BGRA2BGR);
  return bgr;
}

std::optional<fs::path> findTextureFile(const fs::path& meshPath, std::string name) {
  std::replace(name.begin(), name.end(), '\\', '/');
  const fs::path given(name);
  const fs::path dir = meshPath.parent_path();
  std::error_code ec;
  for (const fs::path& candidate :
       {given.is_absolute() ? given : dir / given, dir / given.filename()}) {
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  return std::nullopt;
}

cv::Mat readTextureFile(const fs::path& meshPath, const std::string& name) {
  const auto file = findTextureFile(meshPath, name);
  if (!file) {
    throwInputError(meshPath, "texture file '" + name + "' not found (looked in " +
                                  meshPath.parent_path().string() + ")");
  }
  cv::Mat image = cv::imread(file->string(), cv::IMREAD_COLOR);
  if (image.empty()) {
    throwInputError(meshPath,
                    "texture file '" + file->string() + "' cannot be decoded as an image");
  }
  return image;
}

// PLY files name their texture in a header comment ("comment TextureFile face.png", MeshLab's
// convention), which assimp does not read.
std::optional<std::string> plyTextureComment(const fs::path& path) {
  std::ifstream stream(path, std::ios::binary);
  std::string line;
  for (int lineNumber = 0; lineNumber < 200 && std::getline(stream, line); ++lineNumber) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line == "end_header") break;
    const std::string key = "comment TextureFile ";
    if (line.compare(0, key.size(), key) == 0) return line.substr(key.size());
  }
  return std::nullopt;
}

std::optional<std::string> materialTexture(const aiMaterial& material) {
  for (const auto type : {aiTextureType_DIFFUSE, aiTextureType_BASE_COLOR}) {
    aiString name;
    if (material.GetTextureCount(type) > 0 &&
        material.GetTexture(type, 0, &name) == aiReturn_SUCCESS && name.length > 0) {
      return std::string(name.C_Str());
    }
  }
  return std::nullopt;
}

cv::Mat materialSwatch(const aiMaterial* material) {
  aiColor4D colour(0.5F, 0.5F, 0.5F, 1.0F);
  if (material != nullptr) material->Get(AI_MATKEY_COLOR_DIFFUSE, colour);
  const auto channel = [](float v) {
    return cv::saturate_cast<uchar>(std::clamp(v, 0.0F, 1.0F) * 255.0F);
  };
  return cv::Mat(4, 4, CV_8UC3,
                 cv::Scalar(channel(colour.b), channel(colour.g), channel(colour.r)));
}

// Packs several images into one atlas (shelves, tallest first, 2-pixel replicated borders so
// mipmaps do not bleed) and remaps each part's UVs into its image's rectangle.
cv::Mat packAtlas(const std::vector<Image>& images, const std::vector<Part>& parts,
                  std::vector<Eigen::Vector2f>& uvs) {
  constexpr int kPad = 2;
  std::vector<int> order(images.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return images[static_cast<std::size_t>(a)].bgr.rows >
           images[static_cast<std::size_t>(b)].bgr.rows;
  });
  double area = 0.0;
  int widest = 0;
  for (const auto& image : images) {
    area += static_cast<double>(image.bgr.cols + 2 * kPad) * (image.bgr.rows + 2 * kPad);
    widest = std::max(widest, image.bgr.cols + 2 * kPad);
  }
  const int atlasWidth = std::max(widest, static_cast<int>(std::ceil(std::sqrt(area))));
  std::vector<cv::Rect> rects(images.size());
  int x = 0;
  int y = 0;
  int shelf = 0;
  for (const int index : order) {
    const cv::Mat& image = images[static_cast<std::size_t>(index)].bgr;
    const int w = image.cols + 2 * kPad;
    const int h = image.rows + 2 * kPad;
    if (x + w > atlasWidth) {
      x = 0;
      y += shelf;
      shelf = 0;
    }
    rects[static_cast<std::size_t>(index)] = cv::Rect(x + kPad, y + kPad, image.cols, image.rows);
    x += w;
    shelf = std::max(shelf, h);
  }
  const int atlasHeight = y + shelf;
  cv::Mat atlas(atlasHeight, atlasWidth, CV_8UC3, cv::Scalar(128, 128, 128));
  for (std::size_t i = 0; i < images.size(); ++i) {
    cv::Mat padded;
    cv::copyMakeBorder(images[i].bgr, padded, kPad, kPad, kPad, kPad, cv::BORDER_REPLICATE);
    const cv::Rect& r = rects[i];
    padded.copyTo(atlas(cv::Rect(r.x - kPad, r.y - kPad, padded.cols, padded.rows)));
  }
  const auto W = static_cast<float>(atlasWidth);
  const auto H = static_cast<float>(atlasHeight);
  for (const Part& part : parts) {
    if (part.image < 0) continue;
    const Image& image = images[static_cast<std::size_t>(part.image)];
    const cv::Rect& r = rects[static_cast<std::size_t>(part.image)];
    for (std::size_t v = part.firstVertex; v < part.firstVertex + part.vertexCount; ++v) {
      Eigen::Vector2f& uv = uvs[v];
      float u = image.swatch ? 0.5F : std::clamp(uv.x(), 0.0F, 1.0F);
      float t = image.swatch ? 0.5F : std::clamp(uv.y(), 0.0F, 1.0F);
      // UV (0,0) is the image's bottom-left; rows count from the top.
      uv = {(static_cast<float>(r.x) + u * static_cast<float>(r.width)) / W,
            1.0F - (static_cast<float>(r.y) + (1.0F - t) * static_cast<float>(r.height)) / H};
    }
  }
  return atlas;
}

class SceneMerger {
 public:
  SceneMerger(const aiScene& scene, const fs::path& path) : scene_(scene), path_(path) {}

  void visit(const aiNode& node, const aiMatrix4x4& parent) {
    const aiMatrix4x4 transform = parent * node.mTransformation;
    for (unsigned i = 0; i < node.mNumMeshes; ++i)
      addMesh(*scene_.mMeshes[node.mMeshes[i]], transform);
    for (unsigned i = 0; i < node.mNumChildren; ++i) visit(*node.mChildren[i], transform);
  }

  TexturedMesh finish(const MeshLoadOptions& options) {
    mesh_.source = path_.string();
    if (mesh_.triangles.empty())
      throwInputError(path_, "the file has no faces (triangles or polygons)");
    if (!allHaveNormals_) mesh_.normals.clear();

    bool anyTexture = false;
    for (const auto& image : images_) anyTexture = anyTexture || !image.swatch;
    if (!anyTexture) {
      if (options.requireTexture) {
        throwInputError(
            path_, "no texture: no material names a texture image (is the .mtl file missing?)");
      }
      mesh_.texture = cv::Mat(1, 1, CV_8UC3, cv::Scalar(128, 128, 128));
      if (!allHaveUvs_) std::fill(mesh_.uvs.begin(), mesh_.uvs.end(), Eigen::Vector2f::Zero());
    } else {
      for (const Part& part : parts_) {
        if (!part.hasUvs && options.requireTexture && part.image >= 0 &&
            !images_[static_cast<std::size_t>(part.image)].swatch) {
          throwInputError(path_, "the mesh has a texture but no texture coordinates");
        }
      }
      if (images_.size() == 1) {
        mesh_.texture = images_.front().bgr;
        if (images_.front().swatch)
          std::fill(mesh_.uvs.begin(), mesh_.uvs.end(), Eigen::Vector2f(0.5F, 0.5F));
      } else {
        mesh_.texture = packAtlas(images_, parts_, mesh_.uvs);
      }
    }
    if (mesh_.normals.empty()) mesh_.computeNormals();
    mesh_.validate();
    return std::move(mesh_);
  }

  // Texture named by the PLY header when assimp gave the material none.
  std::optional<std::string> fallbackTexture;

 private:
  int imageFor(unsigned materialIndex) {
    if (const auto it = imageOfMaterial_.find(materialIndex); it != imageOfMaterial_.end())
      return it->second;
    const aiMaterial* material =
        materialIndex < scene_.mNumMaterials ? scene_.mMaterials[materialIndex] : nullptr;
    std::optional<std::string> name =
        material != nullptr ? materialTexture(*material) : std::nullopt;
    if (!name) name = fallbackTexture;
    Image image;
    std::string key;
    if (name) {
      key = "texture:" + *name;
      if (const aiTexture* embedded = scene_.GetEmbeddedTexture(name->c_str());
          embedded != nullptr) {
        image.bgr = decodeEmbedded(*embedded);
        if (image.bgr.empty())
          throwInputError(path_, "embedded texture '" + *name + "' cannot be decoded");
      } else if (!name->empty() && name->front() == '*') {
        throwInputError(path_, "embedded texture '" + *name + "' is missing");
      } else {
        image.bgr = readTextureFile(path_, *name);
      }
    } else {
      image.bgr = materialSwatch(material);
      image.swatch = true;
      const cv::Vec3b c = image.bgr.at<cv::Vec3b>(0, 0);
      key = "swatch:" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," +
            std::to_string(c[2]);
    }
    int index = -1;
    if (const auto it = imageOfKey_.find(key); it != imageOfKey_.end()) {
      index = it->second;
    } else {
      index = static_cast<int>(images_.size());
      images_.push_back(std::move(image));
      imageOfKey_[key] = index;
    }
    imageOfMaterial_[materialIndex] = index;
    return index;
  }

  void addMesh(const aiMesh& source, const aiMatrix4x4& transform) {
    if ((source.mPrimitiveTypes & (aiPrimitiveType_TRIANGLE | aiPrimitiveType_POLYGON)) == 0)
      return;
    Part part;
    part.firstVertex = mesh_.positions.size();
    part.vertexCount = source.mNumVertices;
    part.hasUvs = source.HasTextureCoords(0);
    part.image = imageFor(source.mMaterialIndex);
    allHaveUvs_ = allHaveUvs_ && part.hasUvs;
    allHaveNormals_ = allHaveNormals_ && source.HasNormals();
    aiMatrix3x3 normalMatrix(transform);
    normalMatrix.Inverse().Transpose();
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
      const aiVector3D p = transform * source.mVertices[v];
      mesh_.positions.emplace_back(p.x, p.y, p.z);
      if (part.hasUvs) {
        mesh_.uvs.emplace_back(source.mTextureCoords[0][v].x, source.mTextureCoords[0][v].y);
      } else {
        mesh_.uvs.emplace_back(0.0F, 0.0F);
      }
      if (source.HasNormals()) {
        aiVector3D n = normalMatrix * source.mNormals[v];
        n.NormalizeSafe();
        mesh_.normals.emplace_back(n.x, n.y, n.z);
      }
    }
    const auto base = static_cast<int>(part.firstVertex);
    for (unsigned f = 0; f < source.mNumFaces; ++f) {
      const aiFace& face = source.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines (triangulated already)
      mesh_.triangles.emplace_back(base + static_cast<int>(face.mIndices[0]),
                                   base + static_cast<int>(face.mIndices[1]),
                                   base + static_cast<int>(face.mIndices[2]));
    }
    parts_.push_back(part);
  }

  const aiScene& scene_;
  fs::path path_;
  TexturedMesh mesh_;
  std::vector<Image> images_;
  std::vector<Part> parts_;
  std::map<unsigned, int> imageOfMaterial_;
  std::map<std::string, int> imageOfKey_;
  bool allHaveUvs_ = true;
  bool allHaveNormals_ = true;
};

}  // namespace

TexturedMesh loadTexturedMesh(const fs::path& path, const MeshLoadOptions& options) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throwInputError(path, "file not found");
  if (!fs::is_regular_file(path, ec)) throwInputError(path, "not a regular file");

  Assimp::Importer importer;
  // Points and lines are of no use to the renderer.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene =
      importer.ReadFile(path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                           aiProcess_SortByPType);
  if (scene == nullptr) {
    const std::string why = importer.GetErrorString();
    if (why.find("No meshes") != std::string::npos || why.find("no meshes") != std::string::npos) {
      throwInputError(path, "the file has no faces (" + why + ")");
    }
    throwInputError(path, "cannot read the mesh: " + why);
  }
  if (scene->mRootNode == nullptr || scene->mNumMeshes == 0) {
    throwInputError(path, "the file has no faces");
  }
  SceneMerger merger(*scene, path);
  if (lower(path.extension().string()) == ".ply") merger.fallbackTexture = plyTextureComment(path);
  merger.visit(*scene->mRootNode, aiMatrix4x4());
  return merger.finish(options);
}

}  // namespace clm3d
