// Autosaves of work not yet saved by the user (scan annotations, ground-truth corrections): the
// GUI writes the current state every few seconds to a sibling folder .clm3d-autosave/ beside the
// real file, removes it when the work is saved or discarded, and offers to recover it when the
// file is opened again after a crash. A crash loses at most one autosave interval.
#pragma once

#include <filesystem>

namespace clm3d {

// folder/.clm3d-autosave/name for folder/name. The caller writes it with the file's own (atomic)
// writer; the folder is created here.
std::filesystem::path autosavePathFor(const std::filesystem::path& file);

// An autosave of `file` exists and is newer than the file (or the file does not exist yet).
bool hasRecoverableAutosave(const std::filesystem::path& file);

// Removes the autosave of `file` (after a save, or when the user declines recovery).
void discardAutosave(const std::filesystem::path& file);

}  // namespace clm3d
