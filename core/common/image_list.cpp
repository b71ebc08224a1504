#include "core/common/image_list.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <string>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"

namespace clm3d {
namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace

bool isImageFile(const fs::path& path) {
  static const std::vector<std::string> kExtensions{".jpg", ".jpeg", ".png", ".ppm", ".bmp"};
  const std::string extension = lowerExtension(path);
  return std::find(kExtensions.begin(), kExtensions.end(), extension) != kExtensions.end();
}

bool isVideoFile(const fs::path& path) {
  static const std::vector<std::string> kExtensions{".mp4", ".avi", ".mov",
                                                    ".mkv", ".m4v", ".webm"};
  const std::string extension = lowerExtension(path);
  return std::find(kExtensions.begin(), kExtensions.end(), extension) != kExtensions.end();
}

namespace {

std::string trimmed(const std::string& line) {
  const auto space = [](unsigned char c) { return std::isspace(c) != 0; };
  auto begin = std::find_if_not(line.begin(), line.end(), space);
  auto end = std::find_if_not(line.rbegin(), std::string::const_reverse_iterator(begin), space);
  return std::string(begin, end.base());
}

std::vector<fs::path> listFiles(const fs::path& folderOrList, bool (*accept)(const fs::path&),
                                const std::string& kinds) {
  std::error_code error;
  const fs::file_status status = fs::status(folderOrList, error);
  if (!fs::exists(status)) throwInputError(folderOrList, "no such folder or image list");
  std::vector<fs::path> images;
  if (fs::is_directory(status)) {
    for (const fs::directory_entry& entry : fs::directory_iterator(folderOrList, error)) {
      if (accept(entry.path()) && !entry.is_directory()) images.push_back(entry.path());
    }
    if (error) throwInputError(folderOrList, "cannot list the folder: " + error.message());
    std::sort(images.begin(), images.end());
    if (images.empty()) {
      throwInputError(folderOrList, "no " + kinds + " in the folder");
    }
    return images;
  }
  std::istringstream lines(readTextFile(folderOrList));
  const fs::path base = folderOrList.parent_path();
  std::string line;
  while (std::getline(lines, line)) {
    const std::string entry = trimmed(line);
    if (entry.empty() || entry.front() == '#') continue;
    const fs::path path(entry);
    images.push_back(path.is_absolute() ? path : base / path);
  }
  if (images.empty()) throwInputError(folderOrList, "the list names no file");
  return images;
}

}  // namespace

std::vector<fs::path> listImages(const fs::path& folderOrList) {
  return listFiles(folderOrList, isImageFile, "image (.jpg, .jpeg, .png, .ppm, .bmp)");
}

std::vector<fs::path> listImagesAndVideos(const fs::path& folderOrList) {
  return listFiles(
      folderOrList, [](const fs::path& path) { return isImageFile(path) || isVideoFile(path); },
      "image (.jpg, .jpeg, .png, .ppm, .bmp) or video (.mp4, .avi, .mov, .mkv, .m4v, .webm)");
}

}  // namespace clm3d
