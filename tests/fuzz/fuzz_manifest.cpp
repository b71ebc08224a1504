// Fuzzes the dataset manifest parser (core/dataset/manifest.hpp): any input must parse or throw
// InputError naming the file. Relative paths resolve against an empty temporary folder, so most
// referenced files are missing; the point is the JSON walk, the field checks and the ranges.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "core/common/error.hpp"
#include "core/dataset/manifest.hpp"

namespace {

const std::filesystem::path& manifestPath() {
  static const std::filesystem::path path = [] {
    const auto folder = std::filesystem::temp_directory_path() / "clm3d-fuzz-manifest";
    std::filesystem::create_directories(folder);
    return folder / "fuzz.json";
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const clm3d::DatasetManifest manifest = clm3d::parseManifest(text, manifestPath());
    // What parses names at least its file and scheme.
    if (manifest.file != manifestPath() || manifest.scheme.empty()) __builtin_trap();
  } catch (const clm3d::InputError&) {
  }
  return 0;
}
