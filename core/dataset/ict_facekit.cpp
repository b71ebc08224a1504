#include "core/dataset/ict_facekit.hpp"

#include <archive.h>
#include <archive_entry.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "core/common/error.hpp"
#include "core/common/json_fields.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/dataset/detail/obj_vertex_picker.hpp"

namespace clm3d {
namespace fs = std::filesystem;

namespace {

constexpr double kIctMillimetresPerUnit = 10.0;  // ICT-FaceKit meshes are in centimetres
constexpr std::size_t kChunk = 1 << 20;
const char* const kNeutralName = "generic_neutral_mesh";

struct ArchiveFree {
  void operator()(archive* a) const { archive_read_free(a); }
};

std::string lowerExtension(const fs::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

// name -> landmark vertices (file units) of every OBJ in the model.
using MeshPoints = std::map<std::string, Eigen::Matrix3Xd>;

void addMesh(MeshPoints& meshes, const fs::path& model, const std::string& entry,
             ObjVertexPicker& picker) {
  Eigen::Matrix3Xd points;
  try {
    points = picker.finish();
  } catch (const std::invalid_argument& e) {
    throwInputError(model, entry + ": " + e.what());
  }
  const std::string name = fs::path(entry).stem().string();
  if (!meshes.emplace(name, std::move(points)).second) {
    throwInputError(model, entry + ": a second mesh named '" + name + "'");
  }
}

bool isNeutral(const std::string& entry) {
  return fs::path(entry).stem().string() == kNeutralName;
}

// neutralText, when given, receives the whole text of the neutral mesh (for its faces and UVs).
MeshPoints readArchive(const fs::path& model, const std::vector<int>& indices,
                       const ProgressCallback& progress, const CancelToken* cancel,
                       std::string* neutralText) {
  std::unique_ptr<archive, ArchiveFree> a(archive_read_new());
  if (!a) throw Error("libarchive: out of memory");
  archive_read_support_filter_all(a.get());
  archive_read_support_format_all(a.get());
  if (archive_read_open_filename(a.get(), model.c_str(), kChunk) != ARCHIVE_OK) {
    throwInputError(model,
                    std::string("cannot open the archive: ") + archive_error_string(a.get()));
  }
  std::error_code ec;
  const double totalBytes =
      static_cast<double>(std::max<std::uintmax_t>(1, fs::file_size(model, ec)));
  MeshPoints meshes;
  archive_entry* entry = nullptr;
  int status = ARCHIVE_OK;
  while ((status = archive_read_next_header(a.get(), &entry)) == ARCHIVE_OK) {
    if (cancel) cancel->throwIfCancelled();
    const char* rawName = archive_entry_pathname(entry);
    const std::string name = rawName ? rawName : "";
    if (archive_entry_filetype(entry) != AE_IFREG || lowerExtension(name) != ".obj") {
      archive_read_data_skip(a.get());
      continue;
    }
    ObjVertexPicker picker(indices);
    std::string* keepText = neutralText && isNeutral(name) ? neutralText : nullptr;
    const void* block = nullptr;
    std::size_t size = 0;
    la_int64_t offset = 0;
    while ((status = archive_read_data_block(a.get(), &block, &size, &offset)) == ARCHIVE_OK) {
      if (cancel) cancel->throwIfCancelled();
      try {
        picker.feed(std::string_view(static_cast<const char*>(block), size));
        if (keepText) keepText->append(static_cast<const char*>(block), size);
      } catch (const std::invalid_argument& e) {
        throwInputError(model, name + ": " + e.what());
      }
    }
    if (status != ARCHIVE_EOF) {
      throwInputError(model, name + ": " + archive_error_string(a.get()));
    }
    addMesh(meshes, model, name, picker);
    if (progress) {
      progress(std::min(1.0, static_cast<double>(archive_filter_bytes(a.get(), -1)) / totalBytes),
               "reading the ICT-FaceKit model");
    }
  }
  if (status != ARCHIVE_EOF) {
    throwInputError(model,
                    std::string("cannot read the archive: ") + archive_error_string(a.get()));
  }
  return meshes;
}

MeshPoints readFolder(const fs::path& model, const std::vector<int>& indices,
                      const ProgressCallback& progress, const CancelToken* cancel,
                      std::string* neutralText) {
  std::vector<fs::path> files;
  double totalBytes = 0.0;
  for (const auto& item : fs::recursive_directory_iterator(model)) {
    if (item.is_regular_file() && lowerExtension(item.path()) == ".obj") {
      files.push_back(item.path());
      totalBytes += static_cast<double>(item.file_size());
    }
  }
  std::sort(files.begin(), files.end());
  MeshPoints meshes;
  std::vector<char> buffer(kChunk);
  double doneBytes = 0.0;
  for (const fs::path& file : files) {
    if (cancel) cancel->throwIfCancelled();
    std::ifstream in(file, std::ios::binary);
    if (!in) throwInputError(file, "cannot read the file");
    ObjVertexPicker picker(indices);
    std::string* keepText = neutralText && isNeutral(file.string()) ? neutralText : nullptr;
    while (in) {
      in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      const auto got = static_cast<std::size_t>(in.gcount());
      if (got == 0) break;
      doneBytes += static_cast<double>(got);
      try {
        picker.feed(std::string_view(buffer.data(), got));
        if (keepText) keepText->append(buffer.data(), got);
      } catch (const std::invalid_argument& e) {
        throwInputError(file, e.what());
      }
    }
    addMesh(meshes, model, fs::relative(file, model).string(), picker);
    if (progress && totalBytes > 0.0) {
      progress(doneBytes / totalBytes, "reading the ICT-FaceKit model");
    }
  }
  return meshes;
}

std::string mirrorName(const std::string& name) {
  if (name.size() > 2 && name[name.size() - 2] == '_') {
    const char side = name.back();
    if (side == 'L') return name.substr(0, name.size() - 1) + "R";
    if (side == 'R') return name.substr(0, name.size() - 1) + "L";
  }
  return {};
}

}  // namespace

std::vector<int> readLandmarkVertexTable(const fs::path& path, const std::string& schemeName,
                                         int schemeSize) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throwInputError(path, "cannot read the file");
  std::ostringstream text;
  text << in.rdbuf();
  const JsonValue root = parseJsonText(text.str(), path.string());
  if (!root.is_object()) throwInputError(path, "expected a JSON object");
  JsonFields fields(root, path.string());
  const std::string scheme = fields.requiredString("scheme");
  if (scheme != schemeName) {
    fields.fail("scheme", "is '" + scheme + "' but the dataset's scheme is '" + schemeName + "'");
  }
  // Documentation for people: the mesh the indices refer to and notes (any JSON) on how they were
  // picked.
  (void)fields.string("mesh", std::string(), true);
  fields.allow({"notes"});
  const auto& vertices = fields.array("vertices");
  fields.rejectUnknown();
  if (static_cast<int>(vertices.size()) != schemeSize) {
    throwInputError(path, "field vertices: has " + std::to_string(vertices.size()) +
                              " entries, the scheme has " + std::to_string(schemeSize) + " points");
  }
  std::vector<int> indices;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!vertices[i].is_number_integer() || vertices[i].get<long long>() < -1 ||
        vertices[i].get<long long>() > 10'000'000) {
      throwInputError(path, "field vertices[" + std::to_string(i) +
                                "]: expected a vertex index (or -1 for a missing point)");
    }
    indices.push_back(vertices[i].get<int>());
  }
  return indices;
}

IctLandmarkBasis loadIctLandmarkBasis(const fs::path& model, const std::vector<int>& vertexIndices,
                                      const ProgressCallback& progress, const CancelToken* cancel) {
  return loadIctBasis(model, vertexIndices, nullptr, progress, cancel);
}

IctLandmarkBasis loadIctBasis(const fs::path& model, const std::vector<int>& vertexIndices,
                              std::string* neutralObjText, const ProgressCallback& progress,
                              const CancelToken* cancel) {
  if (neutralObjText) neutralObjText->clear();
  std::error_code ec;
  MeshPoints meshes = fs::is_directory(model, ec)
                          ? readFolder(model, vertexIndices, progress, cancel, neutralObjText)
                          : readArchive(model, vertexIndices, progress, cancel, neutralObjText);
  const auto neutral = meshes.find(kNeutralName);
  if (neutral == meshes.end()) {
    throwInputError(model, std::string("holds no ") + kNeutralName + ".obj");
  }
  IctLandmarkBasis basis;
  basis.neutral = neutral->second * kIctMillimetresPerUnit;
  const std::regex identityName("identity[0-9]+");
  for (const auto& [name, points] : meshes) {  // std::map: sorted by name
    if (name == kNeutralName) continue;
    const Eigen::Matrix3Xd delta = points * kIctMillimetresPerUnit - basis.neutral;
    if (std::regex_match(name, identityName)) {
      basis.identities.push_back(delta);
    } else {
      basis.expressionNames.push_back(name);
      basis.expressions.push_back(delta);
    }
  }
  if (basis.identities.empty()) throwInputError(model, "holds no identityNNN.obj meshes");
  return basis;
}

Eigen::Matrix3Xd sampleIctLandmarks(const IctLandmarkBasis& basis, const IctSampling& sampling,
                                    std::uint64_t seed, std::uint64_t index) {
  SplitMixRandom seeder(seed ^ 0x1C7FACE000000000ULL);
  SplitMixRandom rng(seeder.next() + index * 0xD1B54A32D192ED03ULL);
  Eigen::Matrix3Xd points = basis.neutral;
  for (const auto& identity : basis.identities) {
    points += (sampling.identityWeightSd * rng.normal()) * identity;
  }
  std::vector<int> pool = sampling.expressionPool;
  const int draws = std::min<int>(sampling.expressionsPerSample, static_cast<int>(pool.size()));
  for (int d = 0; d < draws && static_cast<std::size_t>(d) < pool.size(); ++d) {
    // Partial Fisher-Yates: pool[d] becomes a uniform choice among the remaining ones.
    const std::size_t remaining = pool.size() - static_cast<std::size_t>(d);
    const std::size_t pick =
        static_cast<std::size_t>(d) +
        std::min(remaining - 1,
                 static_cast<std::size_t>(rng.unit() * static_cast<double>(remaining)));
    std::swap(pool[static_cast<std::size_t>(d)], pool[pick]);
    const int chosen = pool[static_cast<std::size_t>(d)];
    const double weight = rng.unit();
    points += weight * basis.expressions[static_cast<std::size_t>(chosen)];
    const std::string partner = mirrorName(basis.expressionNames[static_cast<std::size_t>(chosen)]);
    if (partner.empty()) continue;
    for (std::size_t k = static_cast<std::size_t>(d) + 1; k < pool.size(); ++k) {
      if (basis.expressionNames[static_cast<std::size_t>(pool[k])] == partner) {
        points += weight * basis.expressions[static_cast<std::size_t>(pool[k])];
        pool.erase(pool.begin() + static_cast<std::ptrdiff_t>(k));  // not drawn again
        break;
      }
    }
  }
  return points;
}

}  // namespace clm3d
