#include "core/dataset/detail/makehuman_target.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <unordered_set>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"

namespace clm3d {
namespace {

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

// Splits off the next whitespace-separated token of `rest`; empty when there is none.
std::string_view nextToken(std::string_view& rest) {
  std::size_t begin = 0;
  while (begin < rest.size() && isSpace(rest[begin])) ++begin;
  std::size_t end = begin;
  while (end < rest.size() && !isSpace(rest[end])) ++end;
  const std::string_view token = rest.substr(begin, end - begin);
  rest.remove_prefix(end);
  return token;
}

bool parseFloat(std::string_view token, float& value) {
  // from_chars does not take a leading '+'; MakeHuman writes ".008" and "-.009", which it takes.
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

}  // namespace

MorphTarget parseMorphTarget(std::string_view text, const std::filesystem::path& file,
                             std::size_t vertexCount) {
  MorphTarget target;
  target.name = file.stem().string();
  std::unordered_set<int> seen;
  int lineNumber = 0;
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    text.remove_prefix(newline == std::string_view::npos ? text.size() : newline + 1);
    ++lineNumber;
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    std::string_view rest = line;
    const std::string_view indexToken = nextToken(rest);
    if (indexToken.empty()) continue;
    long long index = -1;
    const auto [end, ec] =
        std::from_chars(indexToken.data(), indexToken.data() + indexToken.size(), index);
    if (ec != std::errc() || end != indexToken.data() + indexToken.size() || index < 0) {
      throwInputError(
          file,
          "expected a vertex index (a non-negative integer), got '" + std::string(indexToken) + "'",
          lineNumber);
    }
    if (static_cast<unsigned long long>(index) >= vertexCount) {
      throwInputError(file,
                      "vertex index " + std::to_string(index) + " is out of range (the mesh has " +
                          std::to_string(vertexCount) + " vertices)",
                      lineNumber);
    }
    Eigen::Vector3f offset;
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view token = nextToken(rest);
      if (token.empty()) {
        throwInputError(file, "expected 'index dx dy dz', the line has too few numbers",
                        lineNumber);
      }
      if (!parseFloat(token, offset[axis])) {
        throwInputError(file, "expected a finite number, got '" + std::string(token) + "'",
                        lineNumber);
      }
    }
    if (!nextToken(rest).empty()) {
      throwInputError(file, "expected 'index dx dy dz', the line has more than four fields",
                      lineNumber);
    }
    if (!seen.insert(static_cast<int>(index)).second) {
      throwInputError(file, "vertex " + std::to_string(index) + " is listed twice", lineNumber);
    }
    target.indices.push_back(static_cast<int>(index));
    target.offsets.push_back(offset);
  }
  return target;
}

MorphTarget readMorphTarget(const std::filesystem::path& file, std::size_t vertexCount) {
  return parseMorphTarget(readTextFile(file), file, vertexCount);
}

void applyMorphTarget(const MorphTarget& target, float weight,
                      std::vector<Eigen::Vector3f>& positions) {
  if (weight == 0.0f) return;
  for (std::size_t k = 0; k < target.indices.size(); ++k) {
    positions.at(static_cast<std::size_t>(target.indices[k])) += weight * target.offsets[k];
  }
}

}  // namespace clm3d
