#include "core/scheme/landmark_file.hpp"

#include <algorithm>
#include <cctype>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/scheme/csv_format.hpp"
#include "core/scheme/ljson_format.hpp"
#include "core/scheme/pts_format.hpp"
#include "core/scheme/scheme_map.hpp"

namespace clm3d {
const Scheme* builtInSchemeOfSize(int count) {
  if (count == Scheme::thesis25().size()) return &Scheme::thesis25();
  if (count == Scheme::ibug68().size()) return &Scheme::ibug68();
  return nullptr;
}

LandmarkFormat landmarkFormatOf(const std::filesystem::path& path) {
  auto extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".pts") return LandmarkFormat::Pts;
  if (extension == ".ljson" || extension == ".json") return LandmarkFormat::Ljson;
  if (extension == ".csv") return LandmarkFormat::Csv;
  throwInputError(path, "unknown landmark file extension \"" + extension +
                            "\" (use .pts, .ljson, .json or .csv)");
}

LandmarkSet readLandmarks(const std::filesystem::path& path, const Scheme* expected) {
  const auto format = landmarkFormatOf(path);
  const auto text = readTextFile(path);
  const auto source = path.string();
  LandmarkSet points;
  switch (format) {
    case LandmarkFormat::Pts:
      points = parsePts(text, source);
      break;
    case LandmarkFormat::Ljson: {
      const auto file = parseLjson(text, source);
      const Scheme* scheme =
          expected != nullptr ? expected : builtInSchemeOfSize(file.points.size());
      points = scheme != nullptr ? applyLjsonLayout(file, *scheme) : file.points;
      // A 68-point layout (landmarker.io) read for thesis25 must be put in iBUG order first.
      if (expected != nullptr && expected->size() != file.points.size() &&
          file.points.size() == Scheme::ibug68().size()) {
        points = applyLjsonLayout(file, Scheme::ibug68());
      }
      break;
    }
    case LandmarkFormat::Csv: {
      const auto file = parseLandmarkCsv(text, source);
      const auto holdsAllIds = [&](const Scheme& scheme) {
        return std::all_of(file.ids.begin(), file.ids.end(),
                           [&](const auto& id) { return scheme.indexOf(id) >= 0; });
      };
      const Scheme* scheme = expected;
      if (scheme == nullptr && holdsAllIds(Scheme::thesis25())) scheme = &Scheme::thesis25();
      if (scheme == nullptr && holdsAllIds(Scheme::ibug68())) scheme = &Scheme::ibug68();
      points = scheme != nullptr ? csvToScheme(file, *scheme, source) : file.points;
      break;
    }
  }
  if (expected == nullptr || points.size() == expected->size()) return points;
  if (const SchemeMap* map = schemeMapFor(points.size(), *expected)) return map->apply(points);
  throwInputError(path, "has " + std::to_string(points.size()) + " points, scheme " +
                            expected->name() + " expects " + std::to_string(expected->size()));
}

void writeLandmarks(const std::filesystem::path& path, const LandmarkSet& points,
                    const Scheme& scheme) {
  const auto format = landmarkFormatOf(path);
  if (points.size() != scheme.size()) {
    throwInputError(path, "cannot write " + std::to_string(points.size()) + " points with scheme " +
                              scheme.name() + " of " + std::to_string(scheme.size()));
  }
  std::string text;
  switch (format) {
    case LandmarkFormat::Pts:
      text = formatPts(points);
      break;
    case LandmarkFormat::Ljson:
      text = formatLjson(points, scheme);
      break;
    case LandmarkFormat::Csv:
      text = formatLandmarkCsv(points, scheme);
      break;
  }
  writeTextAtomically(path, text);
}

std::optional<std::filesystem::path> findLandmarkFile(const std::filesystem::path& folder,
                                                      const std::string& stem) {
  for (const char* extension : {".pts", ".ljson", ".csv"}) {
    const std::filesystem::path candidate = folder / (stem + extension);
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error)) return candidate;
  }
  return std::nullopt;
}

}  // namespace clm3d
