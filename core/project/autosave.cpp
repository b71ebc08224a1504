#include "core/project/autosave.hpp"

#include <system_error>

namespace clm3d {

namespace fs = std::filesystem;

fs::path autosavePathFor(const fs::path& file) {
  const fs::path folder = fs::absolute(file).parent_path() / ".clm3d-autosave";
  std::error_code ignored;
  fs::create_directories(folder, ignored);
  return folder / file.filename();
}

bool hasRecoverableAutosave(const fs::path& file) {
  const fs::path autosave = fs::absolute(file).parent_path() / ".clm3d-autosave" / file.filename();
  std::error_code error;
  if (!fs::exists(autosave, error)) return false;
  if (!fs::exists(file, error)) return true;
  const auto saved = fs::last_write_time(file, error);
  if (error) return true;
  const auto autosaved = fs::last_write_time(autosave, error);
  return !error && autosaved > saved;
}

void discardAutosave(const fs::path& file) {
  std::error_code ignored;
  fs::remove(fs::absolute(file).parent_path() / ".clm3d-autosave" / file.filename(), ignored);
}

}  // namespace clm3d
