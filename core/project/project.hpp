// A clm3d project: a folder holding a dataset manifest, scans and their annotations, trained
// models, videos, tracks and ground-truth sets, described by clm3d-project.json in the folder
// (format in docs/studio.md). Paths in the file are relative to the folder, so a project can be
// moved or copied as a whole. The GUI opens projects; `clm3d demo` writes one.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace clm3d {

struct Project {
  static constexpr const char* kFileName = "clm3d-project.json";

  std::filesystem::path folder;    // absolute; the file is folder / kFileName
  std::string name;                // shown in the title bar; defaults to the folder's name
  std::filesystem::path manifest;  // the training dataset manifest (docs/dataset.md); may be empty
  std::vector<std::filesystem::path> models;       // trained .clm3d files
  std::vector<std::filesystem::path> videos;       // videos to track
  std::vector<std::filesystem::path> tracks;       // tracker outputs (docs/tracks-csv.md)
  std::vector<std::filesystem::path> groundTruth;  // ground-truth sets (the tracker's columns)
  // The studio Track page's tracker: the model it tracks with (empty = the first of `models`) and
  // the tracker options changed from their defaults, by the names and in the text `clm3d track`
  // takes them (core/track/tracker_options.hpp; the project does not judge them).
  std::filesystem::path trackerModel;
  std::map<std::string, std::string> trackerOptions;

  std::filesystem::path file() const { return folder / kFileName; }
  // Makes p absolute against the folder (absolute paths stay as they are).
  std::filesystem::path resolve(const std::filesystem::path& p) const;
  // Adds p to list unless it is there already (compared after resolving); returns whether added.
  bool addUnique(std::vector<std::filesystem::path>& list, const std::filesystem::path& p) const;
};

// Reads folder/clm3d-project.json (or the file itself when given). Paths come back absolute.
// Throws InputError naming the file for a missing file, bad JSON, a wrong format tag or version,
// or a field of the wrong type.
Project loadProject(const std::filesystem::path& folderOrFile);

// The same from the file's text: `folder` is where the file lies (paths are resolved against it)
// and `file` names it in error messages.
Project parseProject(std::string_view text, const std::filesystem::path& folder,
                     const std::filesystem::path& file);

// Writes project.file() atomically, creating the folder if needed; paths inside the folder are
// stored relative to it.
void saveProject(const Project& project);

// A new empty project in `folder` (created if missing), saved at once. Throws InputError if the
// folder already holds a project.
Project createProject(const std::filesystem::path& folder, const std::string& name = {});

}  // namespace clm3d
