// Reading and writing landmark files by extension: .pts (iBUG), .ljson / .json (menpo LJSON) and
// .csv, with the conventions of each format (pts_format.hpp, ljson_format.hpp, csv_format.hpp)
// so that callers only ever see 0-based (x, y[, z]) points in scheme order.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

enum class LandmarkFormat { Pts, Ljson, Csv };

// The built-in scheme (thesis25, ibug68) with this many points, or nullptr: how a file or table
// without a scheme's name is given one.
const Scheme* builtInSchemeOfSize(int count);

// By extension (case-insensitive); throws InputError naming the file for any other extension.
LandmarkFormat landmarkFormatOf(const std::filesystem::path& path);

// Reads a landmark file. With `expected`, the points come back in its order (LJSON layouts and CSV
// ids are applied) and must number expected->size(), else InputError "FILE: has 68 points, scheme
// thesis25 expects 25" - except that a file in a scheme with a built-in map to `expected`
// (schemeMapFor: iBUG's 68 points, AFLW's 21, read for thesis25) is converted by the map; the
// points without a counterpart, and AFLW's invisible ones, are then missing (docs/landmarks.md).
// Without `expected`, LJSON layouts of the built-in scheme of the same size apply, and CSV rows are
// placed in the built-in scheme holding all their ids (else kept in file order).
LandmarkSet readLandmarks(const std::filesystem::path& path, const Scheme* expected = nullptr);

// The landmark file STEM.pts, STEM.ljson or STEM.csv in `folder` (the first that exists, in that
// order), or nothing.
std::optional<std::filesystem::path> findLandmarkFile(const std::filesystem::path& folder,
                                                      const std::string& stem);

// Writes atomically in the format of the extension; ids and labels come from the scheme, whose
// size must match (InputError otherwise).
void writeLandmarks(const std::filesystem::path& path, const LandmarkSet& points,
                    const Scheme& scheme);

}  // namespace clm3d
