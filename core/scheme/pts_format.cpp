#include "core/scheme/pts_format.hpp"

#include <cmath>
#include <optional>
#include <vector>

#include "core/common/error.hpp"
#include "core/scheme/text_scan.hpp"

namespace clm3d {

LandmarkSet parsePts(std::string_view text, const std::string& sourceName) {
  const auto lines = text::splitLines(text);
  std::size_t next = 0;
  std::optional<long long> declared;
  int lastLine = 0;

  // Header: "key: value" lines up to the opening brace.
  for (; next < lines.size(); ++next) {
    const auto& line = lines[next];
    lastLine = line.number;
    const auto content = text::trim(line.text);
    if (content.empty() || content.front() == '#') continue;
    if (content == "{") break;
    const auto colon = content.find(':');
    if (colon == std::string_view::npos) {
      if (!text::parseNumberOrNan(text::splitWhitespace(content).front())) {
        throwInputError(sourceName, "expected a header line \"key: value\" or \"{\"", line.number);
      }
      throwInputError(sourceName, "points before the opening \"{\"", line.number);
    }
    const auto key = text::trim(content.substr(0, colon));
    const auto value = text::trim(content.substr(colon + 1));
    if (key == "version") {
      if (value != "1" && value != "1.0") {
        throwInputError(sourceName,
                        "unsupported version \"" + std::string(value) + "\" (expected 1)",
                        line.number);
      }
    } else if (key == "n_points" || key == "npoints") {
      const auto count = text::parseCount(value, text::kMaxLandmarkCount);
      if (!count) {
        throwInputError(sourceName,
                        std::string(key) + " must be a non-negative integer, not \"" +
                            std::string(value) + "\"",
                        line.number);
      }
      if (*count > text::kMaxLandmarkCount) {
        throwInputError(sourceName,
                        std::string(key) + " is too large (at most " +
                            std::to_string(text::kMaxLandmarkCount) + " points)",
                        line.number);
      }
      declared = *count;
    }
    // Other keys (image_size_x, ...) are written by some tools and carry nothing we need.
  }
  if (next >= lines.size()) {
    throwInputError(sourceName, "no opening \"{\" before the points", lastLine);
  }
  if (!declared) {
    throwInputError(sourceName, "header has no \"n_points: N\" line", lines[next].number);
  }
  ++next;

  // Points up to the closing brace.
  std::vector<std::vector<double>> rows;
  int dims = 0;
  bool closed = false;
  for (; next < lines.size(); ++next) {
    const auto& line = lines[next];
    lastLine = line.number;
    const auto content = text::trim(line.text);
    if (content.empty()) continue;
    if (content == "}") {
      closed = true;
      ++next;
      break;
    }
    const auto tokens = text::splitWhitespace(content);
    if (tokens.size() != 2 && tokens.size() != 3) {
      throwInputError(sourceName,
                      "expected \"x y\" or \"x y z\" (or \"}\"), found " +
                          std::to_string(tokens.size()) + " values",
                      line.number);
    }
    if (dims == 0) dims = static_cast<int>(tokens.size());
    if (static_cast<int>(tokens.size()) != dims) {
      throwInputError(sourceName,
                      "has " + std::to_string(tokens.size()) +
                          " coordinates, earlier points have " + std::to_string(dims),
                      line.number);
    }
    if (static_cast<long long>(rows.size()) >= *declared) {
      throwInputError(
          sourceName,
          "more points than n_points = " + std::to_string(*declared) + " (or a missing \"}\")",
          line.number);
    }
    std::vector<double> row;
    int nanCount = 0;
    for (const auto token : tokens) {
      const auto value = text::parseNumberOrNan(token);
      if (!value) {
        throwInputError(sourceName, "\"" + std::string(token) + "\" is not a finite number",
                        line.number);
      }
      nanCount += std::isnan(*value) ? 1 : 0;
      row.push_back(*value);
    }
    if (nanCount != 0 && nanCount != dims) {
      throwInputError(sourceName, "a missing point must be \"nan\" in every coordinate",
                      line.number);
    }
    rows.push_back(std::move(row));
  }
  if (!closed) {
    throwInputError(sourceName, "file ends without the closing \"}\"", lastLine);
  }
  for (; next < lines.size(); ++next) {
    if (!text::trim(lines[next].text).empty()) {
      throwInputError(sourceName, "unexpected text after the closing \"}\"", lines[next].number);
    }
  }
  if (static_cast<long long>(rows.size()) != *declared) {
    throwInputError(sourceName,
                    "n_points says " + std::to_string(*declared) + " but " +
                        std::to_string(rows.size()) + " points follow",
                    lastLine);
  }

  LandmarkSet points(static_cast<int>(rows.size()), dims == 0 ? 2 : dims);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    if (std::isnan(row[0])) continue;
    const Eigen::Vector3d p(row[0] - 1.0, row[1] - 1.0, dims == 3 ? row[2] : 0.0);
    points.set(static_cast<int>(i), p);
  }
  return points;
}

std::string formatPts(const LandmarkSet& points) {
  std::string out = "version: 1\nn_points: " + std::to_string(points.size()) + "\n{\n";
  for (int i = 0; i < points.size(); ++i) {
    if (!points.has(i)) {
      out += points.dims() == 3 ? "nan nan nan\n" : "nan nan\n";
      continue;
    }
    const auto p = points.point(i);
    out += text::formatNumber(p.x() + 1.0) + " " + text::formatNumber(p.y() + 1.0);
    if (points.dims() == 3) out += " " + text::formatNumber(p.z());
    out += "\n";
  }
  out += "}\n";
  return out;
}

}  // namespace clm3d
