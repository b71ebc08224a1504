#include "core/common/error.hpp"

namespace clm3d {

std::string fileMessage(const std::filesystem::path& file, const std::string& what, int line) {
  std::string message = file.string();
  if (line > 0) message += ":" + std::to_string(line);
  return message + ": " + what;
}

void throwInputError(const std::filesystem::path& file, const std::string& what, int line) {
  throw InputError(fileMessage(file, what, line));
}

}  // namespace clm3d
