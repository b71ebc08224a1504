// Writes a dataset manifest (docs/dataset.md), so programs that make a dataset (`clm3d demo`'s
// procedural heads) produce a file loadManifest reads back instead of building JSON by hand.
// Paths inside the manifest's folder are stored relative to it, others absolute.
#pragma once

#include <filesystem>
#include <string>

#include "core/dataset/manifest.hpp"

namespace clm3d {

// The manifest's JSON text for a file in `folder`: version, name, scheme, scans, procedural
// sources and the augmentation, with every field written (defaults included). Throws Error for
// sources this writer does not write yet (ict, ict_textured, makehuman, photos), rather than
// leaving them out silently.
std::string formatManifest(const DatasetManifest& manifest, const std::filesystem::path& folder);

// Writes formatManifest(manifest, path's folder) to path atomically (write, then rename).
void saveManifest(const DatasetManifest& manifest, const std::filesystem::path& path);

}  // namespace clm3d
