// Axis names as manifests and the command line write them ("+y", "-z", "x"), for saying how a
// scan's file axes relate to the model convention (+x subject's left, +y up, +z out of the face).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "core/dataset/manifest.hpp"

namespace clm3d {

// "+x", "-x", "x" (= "+x"), likewise y and z, case-insensitive; nullopt for anything else.
std::optional<Eigen::Vector3d> axisFromName(std::string_view name);

// An option's check of an axis name: InputError "expected an axis such as +y, -z or x, got ...".
void checkAxisName(std::string_view name);

// The file axes --up and --front name, as unit vectors; UsageError naming the option for a bad
// name and "--up/--front" for axes that are not perpendicular.
std::pair<Eigen::Vector3d, Eigen::Vector3d> fileAxes(const std::string& up,
                                                     const std::string& front);

// One textured scan as the command line describes it (--mesh/--scan, --landmarks, --up, --front,
// --scale), as the manifest entry core loads scans from (loadScanSubject), so `clm3d synth` and
// `clm3d ict-texture` put a scan into model coordinates exactly as training does. UsageError
// naming the options for a bad or non-perpendicular axis; the subject is the mesh file's stem,
// the expression "neutral".
ScanSource scanFromAxes(const std::filesystem::path& mesh, const std::filesystem::path& landmarks,
                        const std::string& up, const std::string& front, double scale);

}  // namespace clm3d
