// clm3d landmarks: convert landmark files between formats (.pts, .ljson, .csv) and from the iBUG
// 68 points to the thesis's 25, and describe a landmark file. All work is done by core/scheme.
#include <iostream>
#include <optional>
#include <string>

#include "app/commands/commands.hpp"
#include "core/common/error.hpp"
#include "core/eval/point_set_error.hpp"
#include "core/scheme/ibug68_conversion.hpp"
#include "core/scheme/landmark_file.hpp"

namespace clm3d::cli {
namespace {

// Reads a landmark file in the scheme given (ibug68, thesis25, SCHEME.json), or else in the
// built-in scheme with as many points; nullopt scheme when none fits and none is given.
struct SchemedPoints {
  std::optional<Scheme> scheme;
  LandmarkSet points;
};

SchemedPoints readWithScheme(const std::filesystem::path& file, const std::string& given) {
  if (!given.empty()) {
    auto scheme = Scheme::byNameOrPath(given);
    auto points = readLandmarks(file, &scheme);
    return {std::move(scheme), std::move(points)};
  }
  auto points = readLandmarks(file);
  if (points.size() == Scheme::ibug68().size()) return {Scheme::ibug68(), std::move(points)};
  if (points.size() == Scheme::thesis25().size()) return {Scheme::thesis25(), std::move(points)};
  return {std::nullopt, std::move(points)};
}

// Converts between schemes: the iBUG 68 -> thesis25 table, else by landmark id.
LandmarkSet convertScheme(const LandmarkSet& points, const Scheme& from, const Scheme& to,
                          const std::filesystem::path& file) {
  if (from.name() == to.name() && from.size() == to.size()) return points;
  if (from.name() == "ibug68" && to.name() == "thesis25") return ibug68ToThesis25(points);
  LandmarkSet result(to.size(), points.dims());
  int shared = 0;
  for (int i = 0; i < to.size(); ++i) {
    const int source = from.indexOf(to.id(i));
    if (source < 0) continue;
    ++shared;
    if (points.has(source)) result.set(i, points.point(source));
  }
  if (shared == 0) {
    throwInputError(file, "no conversion from scheme " + from.name() + " to " + to.name() +
                              " (they share no landmark id)");
  }
  return result;
}

std::string formatName(LandmarkFormat format) {
  switch (format) {
    case LandmarkFormat::Pts:
      return "iBUG .pts";
    case LandmarkFormat::Ljson:
      return "menpo LJSON";
    case LandmarkFormat::Csv:
      return "CSV";
  }
  return "?";
}

struct ConvertOptions {
  std::string in;
  std::string out;
  std::string from;
  std::string to;
  std::string keep;
};

void runConvert(const ConvertOptions& options) {
  const std::filesystem::path in(options.in);
  const std::filesystem::path out(options.out);
  landmarkFormatOf(out);  // fail on a bad output name before reading anything
  const auto read = readWithScheme(in, options.from);
  if (!read.scheme) {
    throwInputError(in, "has " + std::to_string(read.points.size()) +
                            " points, which no built-in scheme has: give --from SCHEME.json");
  }
  const auto& from = *read.scheme;
  const auto& points = read.points;
  const auto to = options.to.empty() ? from : Scheme::byNameOrPath(options.to);
  auto converted = convertScheme(points, from, to, in);
  if (!options.keep.empty()) {
    std::vector<int> kept;
    try {
      kept = parsePointList(options.keep, to);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("--keep: ") + e.what());
    }
    for (int i = 0; i < converted.size(); ++i) {
      if (std::find(kept.begin(), kept.end(), i) == kept.end()) converted.setMissing(i);
    }
  }
  writeLandmarks(out, converted, to);
  std::cout << "wrote " << out.string() << ": " << converted.size() << " points ("
            << converted.presentCount() << " present, " << converted.dims() << "D), scheme "
            << to.name() << "\n";
}

void runInfo(const std::string& file, const std::string& schemeName) {
  const std::filesystem::path path(file);
  const auto format = landmarkFormatOf(path);
  const auto read = readWithScheme(path, schemeName);
  const auto& scheme = read.scheme;
  const auto& points = read.points;
  std::cout << "file: " << path.string() << "\n"
            << "format: " << formatName(format) << "\n"
            << "points: " << points.size() << "\n"
            << "dimensions: " << points.dims() << "\n"
            << "scheme: " << (scheme ? scheme->name() : std::string("unknown")) << "\n"
            << "present: " << points.presentCount() << "\n"
            << "missing: " << points.size() - points.presentCount() << "\n";
  for (int i = 0; i < points.size(); ++i) {
    if (points.has(i)) continue;
    std::cout << "  " << i + 1 << " ";
    if (scheme) {
      std::cout << scheme->id(i) << " (" << scheme->label(i) << ")";
    } else {
      std::cout << "point " << i + 1;
    }
    std::cout << "\n";
  }
}

}  // namespace

void addLandmarksCommand(CLI::App& root) {
  auto* landmarks = root.add_subcommand(
      "landmarks",
      "Convert and inspect landmark files (.pts, .ljson, .csv; see docs/landmarks.md)");
  landmarks->require_subcommand(1);

  auto convertOptions = std::make_shared<ConvertOptions>();
  auto* convert = landmarks->add_subcommand(
      "convert", "Convert a landmark file to another format (by extension) and/or scheme");
  convert->add_option("--in", convertOptions->in, "Input landmark file")->required();
  convert->add_option("--out", convertOptions->out, "Output landmark file (.pts, .ljson, .csv)")
      ->required();
  convert->add_option("--from", convertOptions->from,
                      "Scheme of the input: ibug68, thesis25 or SCHEME.json "
                      "(default: from the point count, 68 = ibug68, 25 = thesis25)");
  convert->add_option("--keep", convertOptions->keep,
                      "Keep only these points of the output scheme (1-based list such as "
                      "8,11,12,15,16 or 1-18,22), the others missing: e.g. a 5-point start");
  convert->add_option("--to", convertOptions->to,
                      "Scheme of the output: thesis25, ibug68 or SCHEME.json (default: as --from)");
  convert->callback([convertOptions] { runConvert(*convertOptions); });

  auto infoFile = std::make_shared<std::string>();
  auto infoScheme = std::make_shared<std::string>();
  auto* info = landmarks->add_subcommand(
      "info", "Print a landmark file's point count, dimensions and missing points by name");
  info->add_option("file", *infoFile, "Landmark file")->required();
  info->add_option("--scheme", *infoScheme,
                   "Scheme of the file: ibug68, thesis25 or SCHEME.json (default: by count)");
  info->callback([infoFile, infoScheme] { runInfo(*infoFile, *infoScheme); });
}

}  // namespace clm3d::cli
