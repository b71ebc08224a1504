// Where a clm3d project keeps its files, in one place for the studio and `clm3d demo`: models in
// models/, videos in videos/, tracker outputs in tracks/<video>-<model>.csv, ground-truth sets in
// ground-truth/<video>/<video>.csv (with their .pts files beside them), autosaves in a
// .clm3d-autosave/ folder beside the file they protect (core/project/autosave.hpp). Also which of
// the project's track and ground-truth files belong to a video, so the studio can list them per
// video. Pure path arithmetic: nothing here touches the disk except where a function says so.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/project/project.hpp"

namespace clm3d {

namespace project_layout {

std::filesystem::path modelsFolder(const std::filesystem::path& projectFolder);
std::filesystem::path videosFolder(const std::filesystem::path& projectFolder);
std::filesystem::path tracksFolder(const std::filesystem::path& projectFolder);
std::filesystem::path groundTruthRoot(const std::filesystem::path& projectFolder);

// models/<stem>.clm3d for a plain file name (".clm3d" typed by the user is not doubled). Throws
// InputError when the name is empty, holds a path separator or starts with a dot.
std::filesystem::path modelFile(const std::filesystem::path& projectFolder,
                                const std::string& name);

// tracks/<video stem>-<model stem>.csv: what tracking `video` with `model` writes.
std::filesystem::path tracksFile(const std::filesystem::path& projectFolder,
                                 const std::filesystem::path& video,
                                 const std::filesystem::path& model);

// ground-truth/<video stem>/<video stem>.csv: the ground truth corrected for `video`; its .pts
// files go into the same folder. Without a project (empty projectFolder) the ground-truth folder
// lies beside the video.
std::filesystem::path groundTruthFile(const std::filesystem::path& projectFolder,
                                      const std::filesystem::path& video);

}  // namespace project_layout

// One tracks or ground-truth CSV of a project, as listed for a video.
struct TrackFileEntry {
  std::filesystem::path path;  // absolute
  bool groundTruth = false;    // from the project's ground-truth list (else its tracks list)
};

// The project's track and ground-truth files that belong to `video`, ground truth first, each in
// list order. A file belongs to a video when it lies in the video's own folder (a synthetic
// sequence's truth.csv), in ground-truth/<video stem>/, or when its name is the video's stem or
// starts with "<video stem>-" (tracks/<video>-<model>.csv). A file that belongs to none of the
// project's videos is listed for every video, so no file of the project is ever out of reach.
std::vector<TrackFileEntry> trackFilesOf(const Project& project,
                                         const std::filesystem::path& video);

// The first of the project's videos that `file` (a track or ground truth) belongs to by the rule
// above, or an empty path when it belongs to none.
std::filesystem::path videoOf(const Project& project, const std::filesystem::path& file);

}  // namespace clm3d
