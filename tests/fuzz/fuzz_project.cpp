// Fuzzes the clm3d-project.json parser: any input must give a project or throw InputError, and a
// parsed project's paths must all be absolute (resolved against the folder) and free of duplicates.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/common/error.hpp"
#include "core/project/project.hpp"

namespace {

void checkList(const std::vector<std::filesystem::path>& list) {
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!list[i].is_absolute()) __builtin_trap();
    if (std::find(list.begin() + static_cast<std::ptrdiff_t>(i) + 1, list.end(), list[i]) !=
        list.end()) {
      __builtin_trap();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const clm3d::Project project = clm3d::parseProject(text, "/fuzz/project", "fuzz.json");
    if (!project.folder.is_absolute()) __builtin_trap();
    if (!project.manifest.empty() && !project.manifest.is_absolute()) __builtin_trap();
    checkList(project.models);
    checkList(project.videos);
    checkList(project.tracks);
    checkList(project.groundTruth);
  } catch (const clm3d::InputError&) {
  }
  return 0;
}
