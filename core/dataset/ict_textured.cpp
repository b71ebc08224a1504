#include "core/dataset/ict_textured.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <tuple>

#include "core/common/error.hpp"
#include "core/dataset/detail/model_frame.hpp"
#include "core/registration/texture_bake.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {
namespace fs = std::filesystem;

namespace {

// Vertex ranges of the ICT-FaceKit topology (its README), inclusive.
struct Range {
  int first, last;
  bool contains(int v) const { return v >= first && v <= last; }
};
constexpr Range kFace{0, 9408};
constexpr Range kHeadNeck{9409, 11247};
constexpr Range kMouthSocket{11248, 13293};
constexpr Range kEyeSockets{13294, 14061};
constexpr Range kEyeballLeft{21451, 23020};
constexpr Range kEyeballRight{23021, 24590};
// The sampling stream of textured ICT heads (plus each entry's seed_offset).
constexpr std::uint64_t kSampleSeed = 0x7E87ED1C7ULL;

bool kept(int v) {
  return kFace.contains(v) || kHeadNeck.contains(v) || kMouthSocket.contains(v) ||
         kEyeSockets.contains(v) || kEyeballLeft.contains(v) || kEyeballRight.contains(v);
}

struct ObjTopology {
  std::vector<Eigen::Vector2f> uvs;
  std::vector<std::vector<std::array<int, 2>>> polygons;  // (vertex, uv) 0-based per corner
};

int parseIndex(std::string_view text, std::size_t count, const fs::path& model, int line) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || value == 0 || static_cast<std::size_t>(std::abs(value)) > count) {
    throwInputError(model, "generic_neutral_mesh.obj: bad index '" + std::string(text) + "'", line);
  }
  return value > 0 ? value - 1 : static_cast<int>(count) + value;
}

ObjTopology parseTopology(const std::string& text, std::size_t vertexCount, const fs::path& model) {
  ObjTopology topology;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("vt ", 0) == 0) {
      std::istringstream fields(line.substr(3));
      float u = 0.0F, v = 0.0F;
      if (!(fields >> u >> v) || !std::isfinite(u) || !std::isfinite(v)) {
        throwInputError(model, "generic_neutral_mesh.obj: bad texture coordinate", number);
      }
      topology.uvs.emplace_back(u, v);
    } else if (line.rfind("f ", 0) == 0) {
      std::istringstream fields(line.substr(2));
      std::string corner;
      std::vector<std::array<int, 2>> polygon;
      while (fields >> corner) {
        const auto slash = corner.find('/');
        if (slash == std::string::npos) {
          throwInputError(model, "generic_neutral_mesh.obj: a face corner without UV", number);
        }
        const auto slash2 = corner.find('/', slash + 1);
        const std::string_view view(corner);
        polygon.push_back(
            {parseIndex(view.substr(0, slash), vertexCount, model, number),
             parseIndex(view.substr(slash + 1, slash2 == std::string::npos ? std::string::npos
                                                                           : slash2 - slash - 1),
                        std::max<std::size_t>(topology.uvs.size(), 1), model, number)});
      }
      if (polygon.size() < 3) {
        throwInputError(model, "generic_neutral_mesh.obj: a face with fewer than 3 corners",
                        number);
      }
      topology.polygons.push_back(std::move(polygon));
    }
  }
  if (topology.polygons.empty()) throwInputError(model, "generic_neutral_mesh.obj has no faces");
  return topology;
}

}  // namespace

IctMeshModel loadIctMeshModel(const fs::path& model, const std::vector<int>& landmarkVertices,
                              const fs::path& vertexTable, const ProgressCallback& progress,
                              const CancelToken* cancel) {
  IctMeshModel out;
  out.file = model;
  for (int v = 0; v <= kEyeballRight.last; ++v) {
    if (kept(v)) out.keptVertices.push_back(v);
  }
  std::string neutralText;
  out.basis = loadIctBasis(model, out.keptVertices, &neutralText, progress, cancel);
  const ObjTopology topology = parseTopology(neutralText, 26719, model);

  std::vector<int> columnOf(static_cast<std::size_t>(kEyeballRight.last) + 1, -1);
  for (std::size_t k = 0; k < out.keptVertices.size(); ++k) {
    columnOf[static_cast<std::size_t>(out.keptVertices[k])] = static_cast<int>(k);
  }
  for (std::size_t p = 0; p < landmarkVertices.size(); ++p) {
    const int v = landmarkVertices[p];
    if (v >= 0 && (v > kEyeballRight.last || columnOf[static_cast<std::size_t>(v)] < 0)) {
      throwInputError(vertexTable, "field vertices[" + std::to_string(p) + "]: vertex " +
                                       std::to_string(v) +
                                       " is not in the regions a textured ICT head keeps");
    }
    out.landmarkColumns.push_back(v < 0 ? -1 : columnOf[static_cast<std::size_t>(v)]);
  }

  // Packed layout: tile 0 (u in [0, 1]) top-left, tile 1 (u in [1, 2]) top-right, left eyeball
  // bottom-left, right eyeball bottom-right.
  std::map<std::tuple<int, int, int>, int> vertexOf;  // (ICT vertex, uv, tile) -> mesh vertex
  for (const auto& polygon : topology.polygons) {
    bool keep = true;
    double meanU = 0.0;
    for (const auto& [v, t] : polygon) {
      keep = keep && v <= kEyeballRight.last && columnOf[static_cast<std::size_t>(v)] >= 0;
      meanU += topology.uvs[static_cast<std::size_t>(t)].x();
    }
    if (!keep) continue;
    meanU /= static_cast<double>(polygon.size());
    const int first = polygon[0][0];
    const int tile = kEyeballLeft.contains(first)    ? 2
                     : kEyeballRight.contains(first) ? 3
                                                     : std::clamp(static_cast<int>(meanU), 0, 1);
    const float col = static_cast<float>(tile % 2), row = tile < 2 ? 1.0F : 0.0F;
    std::vector<int> corners;
    for (const auto& [v, t] : polygon) {
      const auto [it, added] =
          vertexOf.emplace(std::make_tuple(v, t, tile), static_cast<int>(out.column.size()));
      if (added) {
        const int c = columnOf[static_cast<std::size_t>(v)];
        out.column.push_back(c);
        out.mesh.positions.push_back(out.basis.neutral.col(c).cast<float>());
        const Eigen::Vector2f uv = topology.uvs[static_cast<std::size_t>(t)];
        const float local =
            std::clamp(uv.x() - (tile < 2 ? static_cast<float>(tile) : 0.0F), 0.0F, 1.0F);
        out.mesh.uvs.emplace_back((local + col) / 2.0F,
                                  (std::clamp(uv.y(), 0.0F, 1.0F) + row) / 2.0F);
        out.skinVertex.push_back(kFace.contains(v) || kHeadNeck.contains(v));
      }
      corners.push_back(it->second);
    }
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {  // fan
      out.mesh.triangles.emplace_back(corners[0], corners[k], corners[k + 1]);
      out.mouthTriangle.push_back(kMouthSocket.contains(first));
    }
  }
  out.mesh.source = model.string();
  out.mesh.computeNormals();
  return out;
}

TexturedMesh ictMeshAt(const IctMeshModel& model, const Eigen::Matrix3Xd& columns,
                       const cv::Mat& texture) {
  TexturedMesh mesh;
  mesh.positions.resize(model.column.size());
  for (std::size_t v = 0; v < model.column.size(); ++v) {
    mesh.positions[v] = columns.col(model.column[v]).cast<float>();
  }
  mesh.uvs = model.mesh.uvs;
  mesh.triangles = model.mesh.triangles;
  mesh.texture = texture;
  mesh.source = model.mesh.source;
  mesh.computeNormals();
  return mesh;
}

LandmarkSet ictLandmarksAt(const IctMeshModel& model, const Eigen::Matrix3Xd& columns) {
  LandmarkSet landmarks(static_cast<int>(model.landmarkColumns.size()), 3);
  for (std::size_t p = 0; p < model.landmarkColumns.size(); ++p) {
    if (model.landmarkColumns[p] >= 0) {
      landmarks.set(static_cast<int>(p), Eigen::Vector3d(columns.col(model.landmarkColumns[p])));
    }
  }
  return landmarks;
}

IctTextureBake bakeScanOntoIct(const IctMeshModel& model, const TexturedMesh& scan,
                               const LandmarkSet& scanLandmarks, int textureSize,
                               const ProgressCallback& progress, const CancelToken* cancel) {
  const auto start = std::chrono::steady_clock::now();
  auto part = [&](double from, double to) {
    return ProgressCallback([&progress, from, to](double f, std::string_view stage) {
      if (progress) progress(from + (to - from) * f, stage);
    });
  };
  // The skin (face, head and neck) is registered; sockets and eyeballs follow it.
  TexturedMesh skin;
  std::vector<int> skinIndex(model.mesh.positions.size(), -1);
  std::vector<Eigen::Vector3f> others;
  std::vector<std::size_t> otherVertices;
  for (std::size_t v = 0; v < model.mesh.positions.size(); ++v) {
    if (model.skinVertex[v]) {
      skinIndex[v] = static_cast<int>(skin.positions.size());
      skin.positions.push_back(model.mesh.positions[v]);
    } else {
      others.push_back(model.mesh.positions[v]);
      otherVertices.push_back(v);
    }
  }
  for (const auto& t : model.mesh.triangles) {
    const Eigen::Vector3i s(skinIndex[static_cast<std::size_t>(t[0])],
                            skinIndex[static_cast<std::size_t>(t[1])],
                            skinIndex[static_cast<std::size_t>(t[2])]);
    if (s.minCoeff() >= 0) skin.triangles.push_back(s);
  }
  skin.source = model.mesh.source;
  // Template landmarks on the skin only (the eye centres are on the eyeballs: left out).
  const LandmarkSet all = ictLandmarksAt(model, model.basis.neutral);
  LandmarkSet templLandmarks(all.size(), 3);
  for (int p = 0; p < all.size(); ++p) {
    const int c = model.landmarkColumns[static_cast<std::size_t>(p)];
    const int vertex = c >= 0 ? model.keptVertices[static_cast<std::size_t>(c)] : -1;
    if (vertex >= 0 && (kFace.contains(vertex) || kHeadNeck.contains(vertex))) {
      templLandmarks.set(p, all.point(p));
    }
  }
  if (scanLandmarks.size() != templLandmarks.size()) {
    throw InputError(scan.source + ": the scan's landmarks have " +
                     std::to_string(scanLandmarks.size()) + " points, the ICT vertex table " +
                     std::to_string(templLandmarks.size()));
  }
  IctTextureBake out;
  try {
    out.registration =
        registerNonRigid(skin, templLandmarks, scan, scanLandmarks, {}, {}, part(0.0, 0.5), cancel);
  } catch (const Cancelled&) {
    throw;
  } catch (const InputError& e) {
    throw InputError(scan.source + ": " + e.what());
  }
  std::vector<Eigen::Vector3f> registered(model.mesh.positions.size());
  for (std::size_t v = 0; v < registered.size(); ++v) {
    if (skinIndex[v] >= 0)
      registered[v] = out.registration.positions[static_cast<std::size_t>(skinIndex[v])];
  }
  const std::vector<Eigen::Vector3f> followed = followRegistration(out.registration, others);
  for (std::size_t k = 0; k < otherVertices.size(); ++k) registered[otherVertices[k]] = followed[k];

  TextureBakeOptions options;
  options.width = options.height = textureSize;
  options.bakeTriangles.resize(model.mesh.triangles.size());
  for (std::size_t t = 0; t < options.bakeTriangles.size(); ++t) {
    options.bakeTriangles[t] = !model.mouthTriangle[t];
  }
  TextureBakeResult baked;
  try {
    baked = bakeTexture(model.mesh, registered, scan, options, part(0.5, 1.0), cancel);
  } catch (const Cancelled&) {
    throw;
  } catch (const InputError& e) {
    throw InputError(scan.source + ": " + e.what());
  }
  // The mouth socket is dark inside, whatever surrounds it in UV space.
  for (std::size_t t = 0; t < model.mesh.triangles.size(); ++t) {
    if (!model.mouthTriangle[t]) continue;
    std::array<cv::Point, 3> corners;
    for (int k = 0; k < 3; ++k) {
      const auto& uv = model.mesh.uvs[static_cast<std::size_t>(model.mesh.triangles[t][k])];
      corners[static_cast<std::size_t>(k)] =
          cv::Point(static_cast<int>(uv.x() * static_cast<float>(textureSize)),
                    static_cast<int>((1.0F - uv.y()) * static_cast<float>(textureSize)));
    }
    cv::fillConvexPoly(baked.texture, corners.data(), 3, cv::Scalar(40, 45, 95), cv::LINE_8);
  }
  out.texture = baked.texture;
  out.bakedFraction = baked.bakedFraction;
  out.registered = model.mesh;
  out.registered.positions = registered;
  out.registered.texture = out.texture;
  out.registered.computeNormals();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

IctTexturedSet prepareIctTextured(const DatasetManifest& manifest, std::size_t entry,
                                  const std::vector<TexturedSubject>& skins, const Scheme& scheme,
                                  const ProgressCallback& progress, const CancelToken* cancel) {
  IctTexturedSet set;
  set.entry = entry;
  set.source = manifest.ictTextured.at(entry);
  const std::string field = "field ict_textured[" + std::to_string(entry) + "]";
  const std::vector<int> indices =
      readLandmarkVertexTable(set.source.vertices, scheme.name(), scheme.size());
  if (indices.empty() || indices[0] < 0) {
    throwInputError(set.source.vertices, "landmark 1, the model's origin, has no vertex");
  }
  const double parts = 1.0 + static_cast<double>(skins.size());
  set.model = loadIctMeshModel(
      set.source.model, indices, set.source.vertices,
      [&](double f, std::string_view stage) {
        if (progress) progress(f / parts, stage);
      },
      cancel);
  set.levelEyes = scheme.name() == "thesis25" || scheme.name() == "ibug68";
  set.sampling.identityWeightSd = set.source.identityWeightSd;
  set.sampling.expressionsPerSample = set.source.expressionsPerSample;
  const auto& names = set.model.basis.expressionNames;
  for (std::size_t e = 0; e < names.size() && set.source.expressions.empty(); ++e) {
    set.sampling.expressionPool.push_back(static_cast<int>(e));
  }
  for (std::size_t k = 0; k < set.source.expressions.size(); ++k) {
    const auto it = std::find(names.begin(), names.end(), set.source.expressions[k]);
    if (it == names.end()) {
      throwInputError(manifest.file, field + ".expressions[" + std::to_string(k) + "]: the model " +
                                         set.source.model.string() + " has no blendshape '" +
                                         set.source.expressions[k] + "'");
    }
    set.sampling.expressionPool.push_back(static_cast<int>(it - names.begin()));
  }
  for (std::size_t i = 0; i < skins.size(); ++i) {
    const IctTextureBake bake = bakeScanOntoIct(
        set.model, skins[i].mesh, skins[i].landmarks, set.source.textureSize,
        [&](double f, std::string_view stage) {
          if (progress) progress((1.0 + static_cast<double>(i) + f) / parts, stage);
        },
        cancel);
    set.textures.push_back(bake.texture);
  }
  return set;
}

TexturedSubject sampleIctTextured(const IctTexturedSet& set, const Scheme& scheme,
                                  std::size_t texture, int index) {
  const std::uint64_t stream =
      static_cast<std::uint64_t>(texture) * static_cast<std::uint64_t>(set.source.identities) +
      static_cast<std::uint64_t>(index);
  const Eigen::Matrix3Xd columns = sampleIctLandmarks(set.model.basis, set.sampling,
                                                      kSampleSeed + set.source.seedOffset, stream);
  const LandmarkSet raw = ictLandmarksAt(set.model, columns);
  std::string why;
  const auto frame = modelFrame(raw, scheme, Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(),
                                set.levelEyes, why);
  if (!frame) throwInputError(set.source.vertices, why);
  Eigen::Matrix3Xd framed(3, columns.cols());
  for (Eigen::Index c = 0; c < columns.cols(); ++c) framed.col(c) = frame->apply(columns.col(c));
  TexturedSubject subject;
  const std::string& name = set.source.textureFrom.at(texture);
  subject.id = ictTexturedSubjectId(set.entry, name, index);
  subject.subject = subject.id;  // each sample is its own identity
  subject.expression = "sampled";
  subject.mesh = ictMeshAt(set.model, framed, set.textures.at(texture));
  subject.landmarks = applyFrame(*frame, raw);
  return subject;
}

}  // namespace clm3d
