#include "core/scheme/text_scan.hpp"

#include <charconv>
#include <cmath>

namespace clm3d::text {

std::vector<Line> splitLines(std::string_view text) {
  std::vector<Line> lines;
  int number = 1;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto end = text.find('\n', start);
    auto line =
        text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (end == std::string_view::npos) {
      if (!line.empty()) lines.push_back({number, line});
      break;
    }
    lines.push_back({number, line});
    ++number;
    start = end + 1;
  }
  return lines;
}

std::string_view trim(std::string_view text) {
  const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
  return text;
}

std::vector<std::string_view> splitWhitespace(std::string_view text) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    const auto start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
    if (i > start) tokens.push_back(text.substr(start, i - start));
  }
  return tokens;
}

std::vector<std::string_view> splitCommas(std::string_view text) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  while (true) {
    const auto comma = text.find(',', start);
    if (comma == std::string_view::npos) {
      cells.push_back(trim(text.substr(start)));
      return cells;
    }
    cells.push_back(trim(text.substr(start, comma - start)));
    start = comma + 1;
  }
}

std::optional<double> parseNumberOrNan(std::string_view token) {
  if (token == "nan" || token == "NaN" || token == "NAN" || token == "-nan") return std::nan("");
  if (token.empty()) return std::nullopt;
  if (token.front() == '+') token.remove_prefix(1);  // from_chars rejects a leading '+'
  double value = 0.0;
  const auto* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<long long> parseCount(std::string_view token, long long limit) {
  if (token.empty()) return std::nullopt;
  long long value = 0;
  for (const char c : token) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + (c - '0');
    if (value > limit) value = limit + 1;  // saturate: the caller reports "too many"
  }
  return value;
}

std::string formatNumber(double value) {
  char buffer[64];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  if (ec != std::errc()) return std::to_string(value);
  return std::string(buffer, ptr);
}

}  // namespace clm3d::text
