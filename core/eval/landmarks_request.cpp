#include "core/eval/landmarks_request.hpp"

#include <algorithm>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/common/error.hpp"
#include "core/eval/point_set_error.hpp"
#include "core/scheme/ibug68_conversion.hpp"
#include "core/scheme/landmark_file.hpp"

namespace clm3d {
namespace landmarks_request_detail {

using R = LandmarksConvertRequest;

std::vector<Option<R>> makeOptions() {
  return {
      textOption<R>(requiredOption("in", "Input landmark file"), &R::in),
      textOption<R>(requiredOption("out", "Output landmark file (.pts, .ljson, .csv)"), &R::out),
      textOption<R>(commandOption("from",
                                  "Scheme of the input: ibug68, thesis25 or SCHEME.json (default: "
                                  "from the point count, 68 = ibug68, 25 = thesis25)"),
                    &R::from),
      textOption<R>(commandOption("keep",
                                  "Keep only these points of the output scheme (1-based list "
                                  "such as 8,11,12,15,16 or 1-18,22), the others missing: e.g. a "
                                  "5-point start"),
                    &R::keep),
      textOption<R>(commandOption("to",
                                  "Scheme of the output: thesis25, ibug68 or SCHEME.json "
                                  "(default: as --from)"),
                    &R::to),
  };
}

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

}  // namespace landmarks_request_detail

const std::vector<Option<LandmarksConvertRequest>>& landmarksConvertOptions() {
  static const std::vector<Option<LandmarksConvertRequest>> table =
      landmarks_request_detail::makeOptions();
  return table;
}

std::string runLandmarksConvert(const LandmarksConvertRequest& options) {
  const std::filesystem::path& in = options.in;
  const std::filesystem::path& out = options.out;
  landmarkFormatOf(out);  // fail on a bad output name before reading anything
  const auto read = landmarks_request_detail::readWithScheme(in, options.from);
  if (!read.scheme) {
    throwInputError(in, "has " + std::to_string(read.points.size()) +
                            " points, which no built-in scheme has: give --from SCHEME.json");
  }
  const auto& from = *read.scheme;
  const auto to = options.to.empty() ? from : Scheme::byNameOrPath(options.to);
  auto converted = landmarks_request_detail::convertScheme(read.points, from, to, in);
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
  std::ostringstream text;
  text << "wrote " << out.string() << ": " << converted.size() << " points ("
       << converted.presentCount() << " present, " << converted.dims() << "D), scheme " << to.name()
       << "\n";
  return text.str();
}

std::string describeLandmarkFile(const std::filesystem::path& path, const std::string& schemeName) {
  const auto format = landmarkFormatOf(path);
  const auto read = landmarks_request_detail::readWithScheme(path, schemeName);
  const auto& scheme = read.scheme;
  const auto& points = read.points;
  std::ostringstream text;
  text << "file: " << path.string() << "\n"
       << "format: " << landmarks_request_detail::formatName(format) << "\n"
       << "points: " << points.size() << "\n"
       << "dimensions: " << points.dims() << "\n"
       << "scheme: " << (scheme ? scheme->name() : std::string("unknown")) << "\n"
       << "present: " << points.presentCount() << "\n"
       << "missing: " << points.size() - points.presentCount() << "\n";
  for (int i = 0; i < points.size(); ++i) {
    if (points.has(i)) continue;
    text << "  " << i + 1 << " ";
    if (scheme) {
      text << scheme->id(i) << " (" << scheme->label(i) << ")";
    } else {
      text << "point " << i + 1;
    }
    text << "\n";
  }
  return text.str();
}

}  // namespace clm3d
