// The options that describe one textured scan on the command line (--mesh/--scan, --landmarks,
// --up, --front, --scale), turned into the manifest entry core loads scans from
// (core/dataset/manifest.hpp ScanSource, loaded by loadScanSubject), so that `clm3d synth` and
// `clm3d ict-texture` put a scan into model coordinates exactly as training does.
#pragma once

#include <filesystem>
#include <string>

#include "core/dataset/manifest.hpp"

namespace clm3d::cli {

// Checks the axis names (CLI::ValidationError naming the option: exit code 2) and returns the
// scan's source; its subject is the mesh file's stem, its expression "neutral".
ScanSource scanFromOptions(const std::filesystem::path& mesh,
                           const std::filesystem::path& landmarks, const std::string& up,
                           const std::string& front, double scale);

}  // namespace clm3d::cli
