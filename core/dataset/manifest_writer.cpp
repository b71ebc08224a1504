#include "core/dataset/manifest_writer.hpp"

#include <nlohmann/json.hpp>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"

namespace clm3d {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

std::string storedPath(const fs::path& path, const fs::path& folder) {
  const fs::path absolute = fs::absolute(path).lexically_normal();
  const fs::path relative = absolute.lexically_relative(fs::absolute(folder).lexically_normal());
  if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
  return absolute.generic_string();
}

}  // namespace

std::string formatManifest(const DatasetManifest& manifest, const fs::path& folder) {
  const auto unsupported = [&](const char* what) {
    throw Error("writing dataset manifest '" + manifest.name + "': " + what +
                " sources are not written by this writer");
  };
  if (!manifest.ict.empty()) unsupported("ict");
  if (!manifest.ictTextured.empty()) unsupported("ict_textured");
  if (!manifest.makehuman.empty()) unsupported("makehuman");
  if (!manifest.photos.empty()) unsupported("photos");
  json top;
  top["version"] = 1;
  top["name"] = manifest.name;
  top["scheme"] = manifest.scheme;
  if (!manifest.scans.empty()) {
    json scans = json::array();
    for (const ScanSource& scan : manifest.scans) {
      scans.push_back({{"mesh", storedPath(scan.mesh, folder)},
                       {"landmarks", storedPath(scan.landmarks, folder)},
                       {"subject", scan.subject},
                       {"expression", scan.expression},
                       {"up", scan.up},
                       {"front", scan.front},
                       {"level_eyes", scan.levelEyes},
                       {"scale", scan.scale}});
    }
    top["scans"] = std::move(scans);
  }
  if (!manifest.procedural.empty()) {
    json procedural = json::array();
    for (const ProceduralSource& source : manifest.procedural) {
      procedural.push_back({{"seeds", source.seeds},
                            {"expressions", source.expressions},
                            {"texture_size", source.textureSize},
                            {"face_step_degrees", source.faceStepDegrees}});
    }
    top["procedural"] = std::move(procedural);
  }
  top["augmentation"] = json::parse(augmentationJson(manifest.augmentation));
  return top.dump(2) + "\n";
}

void saveManifest(const DatasetManifest& manifest, const fs::path& path) {
  writeTextAtomically(path, formatManifest(manifest, path.parent_path()));
}

}  // namespace clm3d
