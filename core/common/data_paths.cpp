#include "core/common/data_paths.hpp"

#include <cstdlib>
#include <system_error>

namespace clm3d {

std::optional<std::filesystem::path> sharedDataDir() {
  std::error_code ec;
  if (const char* env = std::getenv("CLM3D_DATA"); env != nullptr && *env != '\0') {
    if (std::filesystem::is_directory(env, ec)) return std::filesystem::path(env);
    return std::nullopt;
  }
  const std::filesystem::path candidates[] = {
#ifdef CLM3D_SOURCE_DIR
      std::filesystem::path(CLM3D_SOURCE_DIR) / ".." / "shared" / "data",
#endif
      std::filesystem::current_path(ec) / ".." / "shared" / "data",
  };
  for (const auto& candidate : candidates) {
    if (std::filesystem::is_directory(candidate, ec)) {
      return std::filesystem::weakly_canonical(candidate, ec);
    }
  }
  return std::nullopt;
}

}  // namespace clm3d
