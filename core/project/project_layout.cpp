#include "core/project/project_layout.hpp"

#include <cctype>
#include <string_view>

#include "core/common/error.hpp"

namespace clm3d {

namespace fs = std::filesystem;

namespace project_layout {

fs::path modelsFolder(const fs::path& projectFolder) {
  return projectFolder / "models";
}

fs::path videosFolder(const fs::path& projectFolder) {
  return projectFolder / "videos";
}

fs::path tracksFolder(const fs::path& projectFolder) {
  return projectFolder / "tracks";
}

fs::path groundTruthRoot(const fs::path& projectFolder) {
  return projectFolder / "ground-truth";
}

fs::path modelFile(const fs::path& projectFolder, const std::string& name) {
  std::string stem = name;
  const auto notSpace = [](char c) { return c != ' ' && c != '\t' && c != '\n' && c != '\r'; };
  while (!stem.empty() && !notSpace(stem.back())) stem.pop_back();
  std::size_t first = 0;
  while (first < stem.size() && !notSpace(stem[first])) ++first;
  stem.erase(0, first);
  constexpr std::string_view kSuffix = ".clm3d";
  if (stem.size() >= kSuffix.size()) {
    std::string tail = stem.substr(stem.size() - kSuffix.size());
    for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (tail == kSuffix) stem.resize(stem.size() - kSuffix.size());
  }
  if (stem.empty()) throw InputError("model name: enter a name for the model file");
  if (stem.find('/') != std::string::npos || stem.find('\\') != std::string::npos ||
      stem.front() == '.') {
    throw InputError("model name '" + name +
                     "': use a plain file name (no folders, not starting with a dot)");
  }
  return modelsFolder(projectFolder) / (stem + ".clm3d");
}

fs::path tracksFile(const fs::path& projectFolder, const fs::path& video, const fs::path& model) {
  return tracksFolder(projectFolder) /
         (video.stem().string() + "-" + model.stem().string() + ".csv");
}

fs::path groundTruthFile(const fs::path& projectFolder, const fs::path& video) {
  const std::string name = video.stem().string();
  const fs::path base = projectFolder.empty() ? video.parent_path() : projectFolder;
  return groundTruthRoot(base) / name / (name + ".csv");
}

}  // namespace project_layout

namespace {

bool belongsTo(const Project& project, const fs::path& file, const fs::path& video) {
  const fs::path resolvedVideo = project.resolve(video).lexically_normal();
  const fs::path resolvedFile = project.resolve(file).lexically_normal();
  const std::string stem = resolvedVideo.stem().string();
  if (resolvedFile.parent_path() == resolvedVideo.parent_path()) return true;
  if (resolvedFile.parent_path() ==
      (project_layout::groundTruthRoot(project.folder) / stem).lexically_normal()) {
    return true;
  }
  const std::string name = resolvedFile.stem().string();
  return name == stem || name.rfind(stem + "-", 0) == 0;
}

}  // namespace

fs::path videoOf(const Project& project, const fs::path& file) {
  for (const fs::path& video : project.videos) {
    if (belongsTo(project, file, video)) return project.resolve(video);
  }
  return {};
}

std::vector<TrackFileEntry> trackFilesOf(const Project& project, const fs::path& video) {
  std::vector<TrackFileEntry> entries;
  const auto add = [&](const std::vector<fs::path>& files, bool groundTruth) {
    for (const fs::path& file : files) {
      const bool mine = belongsTo(project, file, video) || videoOf(project, file).empty();
      if (mine) entries.push_back({project.resolve(file), groundTruth});
    }
  };
  add(project.groundTruth, true);
  add(project.tracks, false);
  return entries;
}

}  // namespace clm3d
